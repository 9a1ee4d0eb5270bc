(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human pepper1 fridge1)
(wait robot)
(pickup human tomato2 fridge1)
; Hey, could you find me something to mix it all in?
