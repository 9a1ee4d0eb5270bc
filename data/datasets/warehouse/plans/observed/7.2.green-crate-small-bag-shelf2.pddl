(right human c4-5 c5-5)
(wait robot)
(right human c5-5 c6-5)
(wait robot)
(right human c6-5 c7-5)
(wait robot)
(down human c7-5 c7-6)
; Can you grab the small bag?
