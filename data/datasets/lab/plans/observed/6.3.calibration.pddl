(move human bench1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human indicator1 cabinet1)
; Would you fetch me the temperature probe from the drawer?
