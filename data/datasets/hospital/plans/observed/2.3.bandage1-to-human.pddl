(move human west-ward reception)
(wait robot)
(ride human reception landing)
(wait robot)
(move human landing corridor)
(wait robot)
(open human corridor storeroom)
; Grab me the pink one in there. Not the towel.
