(move human counter1 cupboard1)
(wait robot)
(pickup human pot1 cupboard1)
; Please take the red tomato from fridge for me.
