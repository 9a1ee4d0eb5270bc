(move human toolwall rack)
(wait robot)
(pickup human leg2 rack)
; Oh, grab the plank too while you're there, would you?
