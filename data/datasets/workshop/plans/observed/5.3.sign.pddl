(pickup human plank2 rack)
; I need something to cut this with.
