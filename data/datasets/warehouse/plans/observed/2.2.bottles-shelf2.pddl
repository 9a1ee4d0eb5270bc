(right human c4-4 c5-4)
(wait robot)
(right human c5-4 c6-4)
(wait robot)
(right human c6-4 c7-4)
; Please put the big bottle on shelf 2.
