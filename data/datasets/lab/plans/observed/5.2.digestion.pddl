(move human bench1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human culture1 fridge1)
(wait robot)
(pickup human enzyme2 fridge1)
; Can you get the rest?
