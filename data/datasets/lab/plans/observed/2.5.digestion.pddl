(move human bench1 drawer1)
(wait robot)
(pickup human pipette2 drawer1)
; oh can you get the enzyme out of teh fridge for me?
