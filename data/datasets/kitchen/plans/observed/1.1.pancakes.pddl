(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human milk1 fridge1)
(wait robot)
(pickup human egg1 fridge1)
; Can you open the cupboard for me, and then fetch the flour?
