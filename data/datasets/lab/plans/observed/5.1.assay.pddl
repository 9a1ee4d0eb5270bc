(move human bench1 drawer1)
; Please you bring the buffer and the enzyme to the bench.
