(move human east-ward lobby)
(wait robot)
(open human lobby storeroom)
(wait robot)
(move human lobby storeroom)
(wait robot)
(pickup human blanket1 storeroom)
; Could you bring down another one of these? It's for bed three.
