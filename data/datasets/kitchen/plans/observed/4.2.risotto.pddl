(move human counter1 pantry1)
(wait robot)
(pickup human rice1 pantry1)
; Can you grab the yellow one from the fridge?
