(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human egg1 fridge1)
; I'll grab the cheese, can you find me something to fry this in?
