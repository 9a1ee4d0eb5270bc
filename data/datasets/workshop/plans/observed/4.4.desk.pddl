(move human toolwall rack)
(wait robot)
(pickup human panel1 rack)
; I'll take care of the drill if you bring the big one over from the bins.
