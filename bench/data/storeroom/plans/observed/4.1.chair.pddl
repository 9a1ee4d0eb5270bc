(pickup human hammer1 toolwall)
(wait robot)
(move human toolwall rack)
; Could you get the small leg out of the chest?
