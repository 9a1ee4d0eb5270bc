(pickup human trowel2 shed)
(wait robot)
(move human shed patio)
(wait robot)
(pickup human compost1 patio)
; Would you open up the greenhouse? I need the big plant out of there.
