(pickup human bracket1 bins)
; Right, um, you grab the board off the rack and I'll, uh, get the screwdriver.
