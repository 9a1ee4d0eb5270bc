(right human c4-5 c5-5)
(wait robot)
(up human c5-5 c5-4)
(wait robot)
(up human c5-4 c5-3)
(wait robot)
(pickup human jar2 c5-3)
; Could you put the small box on shelf two?
