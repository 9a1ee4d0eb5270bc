(move human bench1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human buffer1 fridge1)
; pipette pls
