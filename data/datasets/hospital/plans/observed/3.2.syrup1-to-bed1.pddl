(move human north-ward landing)
(wait robot)
(ride human landing lobby)
; The syrup goes on the first bed. Can you see to it?
