(move human north-ward landing)
(wait robot)
(ride human landing lobby)
(wait robot)
(open human lobby office)
; Pass me a thermometer, would you? Not the grey one.
