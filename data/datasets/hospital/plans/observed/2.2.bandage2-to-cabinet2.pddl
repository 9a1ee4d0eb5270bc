(move human west-ward reception)
(wait robot)
(ride human reception landing)
; Put the large bandage in the second cabinet, please.
