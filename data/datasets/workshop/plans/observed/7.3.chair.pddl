(pickup human drill1 toolwall)
(wait robot)
(move human toolwall bins)
; Can you bring the small one from the rack?
