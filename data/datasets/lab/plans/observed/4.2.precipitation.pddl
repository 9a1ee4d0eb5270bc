(pickup human pipette1 shelf1)
; Can you bring me the sample that goes with this?
