(move human bench rack)
(wait robot)
(pickup human leg1 rack)
; Could you get me what I need to put it together?
