(move human east-ward landing)
(wait robot)
(ride human landing reception)
(wait robot)
(move human reception kitchen)
(wait robot)
(pickup human keycard1 kitchen)
; Can you carry the white ones up to cabinet 2? I'll go and unlock it.
