(move human bench1 drawer1)
(wait robot)
(pickup human thermometer1 drawer1)
; Would you mind opening the fridge and bringing the big blue bottle over?
