(move human bench1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human culture1 fridge1)
; OK so I'll get the rest myself, and you, could you fetch the reagent from the cabinet?
