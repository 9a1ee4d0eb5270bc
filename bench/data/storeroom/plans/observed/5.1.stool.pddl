(open human trunk cellar)
(wait robot)
(take human leg2 trunk cellar)
; Can you get the big wrench from the locker?
