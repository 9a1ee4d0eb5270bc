(move human bench1 shelf1)
(wait robot)
(pickup human thermometer1 shelf1)
; Right, hydrolysis next. I'll get what's in the cabinet, could you deal with the fridge side of things?
