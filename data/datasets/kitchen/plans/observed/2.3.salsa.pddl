(move human counter1 pantry1)
(wait robot)
(pickup human onion1 pantry1)
; I'll get the knife, can you bring over the rest from the fridge?
