(move human south-ward landing)
(wait robot)
(ride human landing lobby)
(wait robot)
(pickup human keycard1 lobby)
; I'm restocking the trolley upstairs.
