(right human c6-6 c7-6)
(wait robot)
(pickup human can2 c7-6)
; I'll put this can away, you fetch the little red box.
