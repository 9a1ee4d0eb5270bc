(move human counter1 pantry1)
(wait robot)
(pickup human onion1 pantry1)
; Could you dig out something to fry it in? I'll grab a spud.
