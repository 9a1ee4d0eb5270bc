(move human bench toolwall)
(wait robot)
(pickup human hammer1 toolwall)
; Can you bring the big plank over to the bench?
