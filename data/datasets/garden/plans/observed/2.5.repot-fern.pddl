(pickup human fern1 greenhouse)
(wait robot)
(move human greenhouse shed)
(wait robot)
(pickup human trowel1 shed)
; I'll take these out to the patio, can you bring the orange one?
