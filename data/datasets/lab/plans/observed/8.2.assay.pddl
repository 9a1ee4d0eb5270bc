(move human bench1 shelf1)
; Bring the blue one and the green one from fridge to bench, please.
