(move human bench1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human acid1 cabinet1)
; hmm, still need a sample for this one
