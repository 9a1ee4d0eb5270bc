(move human treatment-room landing)
(wait robot)
(move human landing west-ward)
; I'm getting bed 2 ready for the new patient, it needs a blanket.
