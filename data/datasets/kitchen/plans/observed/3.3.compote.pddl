(pickup human sugar1 pantry1)
; Um, could you open the fridge and grab the, uh, the small one?
