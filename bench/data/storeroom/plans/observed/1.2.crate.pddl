(move human rack toolwall)
(wait robot)
(pickup human key1 toolwall)
; Could you get the small plank from the cupboard?
