(move human rosebed patio)
(wait robot)
(pickup human key1 patio)
; I've got the shed. Can you do the greenhouse and bring the rose over to the bed?
