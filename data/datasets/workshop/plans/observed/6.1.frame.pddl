(pickup human bracket2 bins)
; Can you fetch the big screwdriver?
