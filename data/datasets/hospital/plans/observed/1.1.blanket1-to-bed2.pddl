(move human east-ward landing)
(wait robot)
(ride human landing lobby)
(wait robot)
(move human lobby corridor)
; Can you take a blanket from the storeroom up to bed 2? Not the white one.
