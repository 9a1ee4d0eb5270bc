(move human counter1 cupboard1)
(wait robot)
(open human cupboard1)
(wait robot)
(pickup human sugar1 cupboard1)
; Meringues today! Could you get an egg from the fridge?
