(move human counter1 cupboard1)
(wait robot)
(pickup human tray1 cupboard1)
; Could you bring the veg from the pantry?
