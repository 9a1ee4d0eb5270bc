(move human counter1 pantry1)
(wait robot)
(pickup human onion1 pantry1)
; Get me an egg from the fridge, will you?
