(move human rack bins)
(wait robot)
(pickup human bracket2 bins)
; Can you bring the big one from the rack?
