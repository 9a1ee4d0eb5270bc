(move human bench1 shelf1)
(wait robot)
(pickup human pipette1 shelf1)
; Set the acid in the fume hood, would you?
