(pickup human trowel1 shed)
(wait robot)
(move human shed patio)
; Oh, it's locked. Would you mind unlocking the greenhouse?
