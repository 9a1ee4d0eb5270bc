(up human)
(wait robot)
(left human)
(wait robot)
(left human)
(wait robot)
; Can you unlock the yellow door for me?
