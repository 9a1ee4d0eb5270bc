(move human counter1 fridge1)
(wait robot)
(open human fridge1)
; Gonna need some grain, and that baking tray.
