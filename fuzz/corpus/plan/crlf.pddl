(pick c table)
(place c b)
; done
