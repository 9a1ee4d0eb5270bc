(move human bench bins)
(wait robot)
(pickup human bracket1 bins)
; Can you fetch the small one from the rack?
