(move human rosebed patio)
(wait robot)
(pickup human key2 patio)
(wait robot)
(unlock human key2 greenhouse patio)
; um, could you go in there and, uh, get me the big one?
