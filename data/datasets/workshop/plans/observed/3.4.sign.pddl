(pickup human plank2 rack)
; See the bins over there? Grab whatever's in them and leave it on the bench.
