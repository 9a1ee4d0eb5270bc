(move human counter1 pantry1)
(wait robot)
(pickup human rice1 pantry1)
; Oh, um, I still need the milk.
