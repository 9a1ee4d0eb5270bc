(move human bench1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human enzyme1 fridge1)
; That red one on the shelf, could you fetch it? It goes with this.
