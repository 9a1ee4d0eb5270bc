(pickup human hammer1 toolwall)
; Could you bring me the plank and the big one?
