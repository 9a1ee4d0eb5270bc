(move human north-ward landing)
(wait robot)
(ride human landing lobby)
(wait robot)
(open human lobby storeroom)
; Can you hand me that small grey one?
