(move human rack toolwall)
(wait robot)
(pickup human hammer1 toolwall)
; Could you bring the big wooden one to the bench?
