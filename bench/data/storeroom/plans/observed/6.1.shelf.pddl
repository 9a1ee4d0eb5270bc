(pickup human bracket1 bins)
(wait robot)
(move human bins rack)
; Can you get the screwdriver out of the chest?
