(move human hood1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human solvent2 cabinet1)
; So we're doing the reflux today, can you give me a hand?
