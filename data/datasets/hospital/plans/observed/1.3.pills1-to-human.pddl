(move human east-ward landing)
(wait robot)
(move human landing nurses-station)
(wait robot)
(pickup human keycard1 nurses-station)
; I'll open the pharmacy, you grab me the yellow pills.
