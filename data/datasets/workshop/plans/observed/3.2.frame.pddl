(pickup human dowel2 rack)
; Can you bring the small one from the bins?
