(pickup human bracket2 bins)
; I'll get the small screwdriver, can you bring the big panel?
