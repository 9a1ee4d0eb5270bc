(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human milk1 fridge1)
; Could you open the cupboard, then grab me some cereal from the pantry?
