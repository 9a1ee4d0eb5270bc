(pickup human drill1 toolwall)
; Chair time. You get the leg, I'll sort out the rest.
