(move human bench loft)
(wait robot)
(pickup human leg1 loft)
; Could you bring the big panel from the trunk?
