(pickup human beaker1 shelf1)
; All that's missing is the cells from the fridge.
