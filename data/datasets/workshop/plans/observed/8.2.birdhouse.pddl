(move human bench toolwall)
(wait robot)
(pickup human saw1 toolwall)
; Can you bring the small plank to the bench?
