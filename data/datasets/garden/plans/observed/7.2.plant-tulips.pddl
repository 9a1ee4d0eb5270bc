(pickup human trowel2 shed)
; I'll grab the compost, could you bring me the flower?
