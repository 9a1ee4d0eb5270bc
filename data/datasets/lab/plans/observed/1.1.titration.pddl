(move human bench1 shelf1)
(wait robot)
(pickup human burette1 shelf1)
; Could you grab the red one for me?
