(pickup human compost1 patio)
(wait robot)
(pickup human mulch1 patio)
; I'll carry these to the rose bed, and you, uh, bring me something to spread it with?
