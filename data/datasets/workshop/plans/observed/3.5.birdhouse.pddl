(pickup human plank2 rack)
; Have you got something I can cut this with?
