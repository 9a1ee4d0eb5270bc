(move human east-ward lobby)
(wait robot)
(open human lobby storeroom)
; Bed two still needs its blanket.
