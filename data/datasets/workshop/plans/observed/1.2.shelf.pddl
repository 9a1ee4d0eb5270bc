(move human bench toolwall)
(wait robot)
(pickup human screwdriver1 toolwall)
; Could you grab the big one for me?
