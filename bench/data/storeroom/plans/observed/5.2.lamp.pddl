(move human cellar bins)
(wait robot)
(pickup human bracket1 bins)
; Could you hand me the drill?
