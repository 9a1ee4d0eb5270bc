(pickup human rod2 rack)
; Could you pass me the small one?
