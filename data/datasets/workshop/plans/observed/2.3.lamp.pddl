(pickup human rod1 rack)
; I'll grab the wrench, could you get the rest?
