(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human egg1 fridge1)
; Meringues it is! Could you get the sugar out of the cupboard for me?
