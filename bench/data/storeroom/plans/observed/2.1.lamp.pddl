(move human bench bins)
(wait robot)
(pickup human bracket1 bins)
; Can you get the drill out of the locker?
