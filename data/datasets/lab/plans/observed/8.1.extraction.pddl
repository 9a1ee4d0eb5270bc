(move human bench1 shelf1)
(wait robot)
(pickup human flask1 shelf1)
(wait robot)
(move human shelf1 hood1)
; Can you bring the red one over here?
