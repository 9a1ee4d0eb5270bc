(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human cheese1 fridge1)
; You can take the big one from pantry, please?
