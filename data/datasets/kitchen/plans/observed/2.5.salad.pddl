(move human counter1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human pepper1 fridge1)
; can u grab the little one too while your there
