(pickup human trowel2 shed)
; Um, would you mind unlocking the greenhouse and bringing out the ones we cook with?
