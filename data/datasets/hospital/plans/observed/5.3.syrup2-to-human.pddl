(move human south-ward landing)
(wait robot)
(ride human landing lobby)
(wait robot)
(pickup human keycard1 lobby)
(wait robot)
(move human lobby corridor)
; I'll open it up. You grab the syrup, but not the green one.
