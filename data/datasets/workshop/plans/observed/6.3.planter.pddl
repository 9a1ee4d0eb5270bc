(pickup human bracket3 bins)
; I'll get the hammer, can you bring the panel over?
