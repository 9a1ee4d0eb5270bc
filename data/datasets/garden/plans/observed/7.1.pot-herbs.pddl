(pickup human trowel1 shed)
; Fetch the small plant from the greenhouse, would you?
