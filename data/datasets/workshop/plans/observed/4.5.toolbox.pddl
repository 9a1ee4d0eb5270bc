(pickup human drill1 toolwall)
(wait robot)
(move human toolwall bins)
(wait robot)
(pickup human bracket1 bins)
; Okay, I'm making the toolbox. Would you mind bringing the panel over from the rack, please?
