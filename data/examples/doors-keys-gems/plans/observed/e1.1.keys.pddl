(left human)
(wait robot)
(left human)
(wait robot)
; Can you get me the yellow key?
