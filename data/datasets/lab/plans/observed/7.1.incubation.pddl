(move human bench1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human culture1 fridge1)
; Could you find me something to check the temperature with?
