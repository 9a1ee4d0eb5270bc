(move human bench1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human acid1 cabinet1)
; Could you grab the little glass one?
