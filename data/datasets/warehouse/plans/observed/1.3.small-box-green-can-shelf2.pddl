(down human c4-4 c4-5)
(wait robot)
(down human c4-5 c4-6)
; Shelf two needs sorting out.
