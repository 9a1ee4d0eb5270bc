(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human cheese1 fridge1)
; I'm going to need the red pan as well.
