(move human bench1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human solvent1 cabinet1)
; Right, distillation next. Could you dig the instrument out of the drawer for me?
