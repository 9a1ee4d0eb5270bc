(move human bench1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human base1 cabinet1)
; could u grab me the little one as well?
