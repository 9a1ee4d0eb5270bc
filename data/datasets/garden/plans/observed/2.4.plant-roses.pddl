(pickup human rose1 greenhouse)
; Gonna need the compost out by the border, and something to dig with.
