(pickup human sugar1 pantry1)
; I'll find a spoon if you can grab the fruit from the fridge.
