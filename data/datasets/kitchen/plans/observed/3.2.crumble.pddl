(pickup human flour1 pantry1)
(wait robot)
(move human pantry1 cupboard1)
(wait robot)
(open human cupboard1)
(wait robot)
(pickup human tray1 cupboard1)
; I still need the butter.
