(left human)
(wait robot)
(left human)
(wait robot)
(left human)
(wait robot)
; I am going left, can you get the red key for me?
