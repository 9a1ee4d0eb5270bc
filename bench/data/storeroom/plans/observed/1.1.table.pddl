(pickup human plank1 rack)
(wait robot)
(pickup human leg1 rack)
; Can you bring me the saw?
