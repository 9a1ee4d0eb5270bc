(move human bench rack)
(wait robot)
(pickup human plank1 rack)
; Can you fetch the hammer?
