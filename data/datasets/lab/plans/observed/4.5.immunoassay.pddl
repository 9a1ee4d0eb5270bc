(pickup human pipette2 shelf1)
; Right, immunoassay next. Could you please put the serum out on the bench for me?
