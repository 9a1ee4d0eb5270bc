(pickup human wrench1 toolwall)
; Can you help me bring the pieces over from the rack?
