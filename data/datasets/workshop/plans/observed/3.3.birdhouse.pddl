(pickup human plank2 rack)
; We need the small saw, can you get it?
