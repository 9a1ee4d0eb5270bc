(up human)
(wait robot)
(up human)
(wait robot)
; Can you bring me the red key?
