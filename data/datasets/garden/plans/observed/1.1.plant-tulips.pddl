(pickup human key1 patio)
(wait robot)
(unlock human key1 shed patio)
(wait robot)
(move human patio shed)
(wait robot)
(pickup human trowel1 shed)
; Could you take the compost over to the border, please?
