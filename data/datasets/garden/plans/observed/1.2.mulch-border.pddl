(pickup human key1 patio)
(wait robot)
(unlock human key1 shed patio)
(wait robot)
(move human patio shed)
(wait robot)
(pickup human rake1 shed)
; grab the compost n the small one and take em to the border pls
