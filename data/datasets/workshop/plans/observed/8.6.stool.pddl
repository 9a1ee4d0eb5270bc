(move human bench cabinet)
(wait robot)
(pickup human drill1 cabinet)
; ugh i still need the little one, can u grab it for me
