(move human bench rack)
(wait robot)
(pickup human dowel1 rack)
; We need the small saw from the locker, can you get it?
