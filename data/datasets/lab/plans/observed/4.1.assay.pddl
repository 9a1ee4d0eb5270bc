(pickup human pipette1 shelf1)
(wait robot)
(move human shelf1 fridge1)
; My hands are full, could you open the fridge so I can get the enzyme out?
