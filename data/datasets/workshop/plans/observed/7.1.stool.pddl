(pickup human drill1 toolwall)
; Can you bring the plank and a wooden leg over to the bench?
