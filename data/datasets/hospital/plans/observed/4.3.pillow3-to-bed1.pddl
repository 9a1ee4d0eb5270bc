(move human east-ward landing)
(wait robot)
(ride human landing reception)
(wait robot)
(move human reception corridor)
; That little green one in there, put it on bed one for me?
