(pickup human panel2 rack)
; Can you bring the small one to the bench?
