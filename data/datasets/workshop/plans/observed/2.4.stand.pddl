(pickup human rod1 rack)
(wait robot)
(move human rack bins)
; I'm gonna need something to knock this together with.
