(move human bench1 shelf1)
(wait robot)
(pickup human solvent1 shelf1)
; Pop the little bottle of acid on the bench for me, would you?
