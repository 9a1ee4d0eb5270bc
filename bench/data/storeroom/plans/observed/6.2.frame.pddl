(move human bins loft)
(wait robot)
(pickup human dowel1 loft)
; Could you grab the big bracket from the cupboard?
