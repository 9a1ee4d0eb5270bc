(pickup human seeds1 greenhouse)
(wait robot)
(pickup human trowel1 greenhouse)
; I need some compost at the veg patch.
