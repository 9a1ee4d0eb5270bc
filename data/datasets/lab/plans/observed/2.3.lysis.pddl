(move human bench1 drawer1)
(wait robot)
(pickup human thermometer1 drawer1)
; hey can u get the red one out of the fridge
