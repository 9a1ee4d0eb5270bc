(move human bench1 fridge1)
(wait robot)
(open human fridge1)
(wait robot)
(pickup human enzyme1 fridge1)
; I'll bring this and the red bottle over; can you find me something for measuring out small amounts?
