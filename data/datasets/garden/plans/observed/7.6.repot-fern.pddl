(pickup human trowel1 shed)
(wait robot)
(move human shed patio)
; Oh, er, could you get the fern out of the greenhouse? Key's by the border, I think.
