(pickup human drill1 toolwall)
; I'll grab the bracket, can you bring the wooden one?
