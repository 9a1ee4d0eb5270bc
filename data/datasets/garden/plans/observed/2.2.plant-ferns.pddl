(move human greenhouse shed)
(wait robot)
(pickup human spade1 shed)
; You can bring the big one from the greenhouse, please?
