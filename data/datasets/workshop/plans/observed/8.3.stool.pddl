(move human bench bins)
(wait robot)
(pickup human leg1 bins)
; I'll get the drill, can you get the plank?
