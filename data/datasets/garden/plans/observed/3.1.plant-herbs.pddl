(pickup human compost1 shed)
; Could you unlock the greenhouse and bring out the green one?
