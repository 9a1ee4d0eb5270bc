(move human bench1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human acid1 cabinet1)
; ok I'll bring the solvent, you bring the burette over to the hood
