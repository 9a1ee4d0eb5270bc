(move human east-ward landing)
(wait robot)
(move human landing west-ward)
; Bed 3 needs a pillow. Any of them except the white one.
