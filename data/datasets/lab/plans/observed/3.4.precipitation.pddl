(move human hood1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human solvent1 cabinet1)
; I'll get the other bottle, you bring the red one that's on the shelf.
