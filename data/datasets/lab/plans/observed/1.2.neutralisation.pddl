(move human bench1 cabinet1)
(wait robot)
(open human cabinet1)
(wait robot)
(pickup human base1 cabinet1)
; Um, I need something to mix this in... could you, uh, find me something?
