(move human north-ward landing)
(wait robot)
(ride human landing lobby)
; Fetch me the white one, please.
