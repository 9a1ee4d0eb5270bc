(pickup human hammer1 toolwall)
(wait robot)
(move human toolwall bins)
(wait robot)
(pickup human rod1 bins)
; Can you bring the dowel from the cupboard?
