(move human treatment-room landing)
(wait robot)
(open human landing laundry)
; The green one's for bed one. Could you?
