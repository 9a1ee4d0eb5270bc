(move human counter1 pantry1)
(wait robot)
(pickup human rice1 pantry1)
; Could you bring over the big carton from the fridge?
