(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human lemon1 fridge1)
; Could you get me the wooden knife, please?
