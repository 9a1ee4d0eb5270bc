(move human bench1 shelf1)
(wait robot)
(pickup human beaker1 shelf1)
; Neutralisation next. Mind getting the cabinet open for me?
