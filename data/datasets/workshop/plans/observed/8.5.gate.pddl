(move human bench cabinet)
; can you bring teh plank and the rod over to the bench?
