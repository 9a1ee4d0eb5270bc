(move human bench1 shelf1)
(wait robot)
(pickup human flask1 shelf1)
; I need the large green bottle from the fridge, can you get it?
