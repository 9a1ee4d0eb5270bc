(move human bench bins)
(wait robot)
(pickup human leg1 bins)
; Could you put another one like this on the bench for me?
