(pickup human hammer1 toolwall)
(wait robot)
(move human toolwall bins)
(wait robot)
(pickup human dowel1 bins)
; Can you bring me the leg that goes with this?
