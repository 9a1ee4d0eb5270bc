(move human rosebed patio)
(wait robot)
(pickup human key1 patio)
; I'll open the shed. Take the yellow one to the rose bed.
