(pickup human key1 patio)
(wait robot)
(unlock human key1 shed patio)
; I'll grab my bits from the shed. You bring the big one over to the patio, yeah?
