(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human milk1 fridge1)
(wait robot)
(pickup human egg1 fridge1)
; Would you mind fetching me something to beat the eggs with, please?
