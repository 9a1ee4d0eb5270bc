(move human counter1 pantry1)
(wait robot)
(pickup human potato1 pantry1)
; Can you open the big cupboard?
