(pickup human sugar1 pantry1)
; Would you mind opening the cupboard and getting the metal one out for me, please?
