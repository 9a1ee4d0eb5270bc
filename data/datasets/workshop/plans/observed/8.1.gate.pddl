(move human bench rack)
(wait robot)
(pickup human rod1 rack)
; Can you get the big one from the cabinet?
