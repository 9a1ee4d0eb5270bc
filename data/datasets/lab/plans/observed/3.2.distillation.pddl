(move human hood1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human acid1 cabinet1)
; Okay, acid's sorted, so when you get a sec could you grab me some glassware off the shelf?
