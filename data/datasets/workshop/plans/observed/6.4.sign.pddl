(pickup human bracket3 bins)
(wait robot)
(move human bins rack)
(wait robot)
(pickup human panel2 rack)
; Doing the sign now. Could you hand me the little one?
