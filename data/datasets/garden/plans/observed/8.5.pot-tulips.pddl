(move human gate patio)
(wait robot)
(pickup human key1 patio)
(wait robot)
(unlock human key1 shed patio)
; can u bring the small red flower from the gate over to the pots
