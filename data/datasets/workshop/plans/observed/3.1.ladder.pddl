(pickup human dowel2 rack)
; Can you get me the saw?
