(move human counter1 pantry1)
(wait robot)
(pickup human banana1 pantry1)
; Hmm, I'll need something sharp for this.
