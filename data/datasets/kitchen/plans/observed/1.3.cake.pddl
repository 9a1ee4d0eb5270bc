(move human counter1 pantry1)
(wait robot)
(pickup human flour1 pantry1)
; I'll grab a bowl. Can you get an egg out of the fridge?
