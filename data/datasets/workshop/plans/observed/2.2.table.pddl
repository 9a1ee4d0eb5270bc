(pickup human panel1 rack)
; Could you bring the wooden one to the bench?
