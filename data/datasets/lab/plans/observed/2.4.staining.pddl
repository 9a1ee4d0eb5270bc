(move human bench1 drawer1)
(wait robot)
(pickup human pipette2 drawer1)
; ok I'll need something to dye the cells with, can you find it?
