(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human cream1 fridge1)
; The wood one from the cupboard, please.
