(move human treatment-room landing)
(wait robot)
(ride human landing reception)
(wait robot)
(move human reception corridor)
(wait robot)
(move human corridor office)
; Could you put some pills in the third cabinet? Any except the green ones.
