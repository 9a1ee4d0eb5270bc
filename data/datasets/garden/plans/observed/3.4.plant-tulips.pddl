(pickup human trowel1 shed)
(wait robot)
(pickup human compost1 shed)
; Greenhouse is still locked, isn't it? Grab me the little one while you're in there.
