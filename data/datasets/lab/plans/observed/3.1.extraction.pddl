(move human hood1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human base1 cabinet1)
; I'll grab the solvent, can you get me a flask?
