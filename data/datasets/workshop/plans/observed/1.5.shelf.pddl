(move human bench toolwall)
(wait robot)
(pickup human screwdriver1 toolwall)
; I need the larger board off the rack, could you get it?
