(pickup human rod1 rack)
; Can you grab the big one?
