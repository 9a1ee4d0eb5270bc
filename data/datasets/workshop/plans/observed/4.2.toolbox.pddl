(pickup human drill1 toolwall)
; Can you bring the metal one from the rack?
