(pickup human trowel1 shed)
; I'll grab a pot, can you get the yellow one?
