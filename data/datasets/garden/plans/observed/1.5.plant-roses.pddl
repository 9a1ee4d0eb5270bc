(move human patio rosebed)
; ok so all i need now is the trowel, its in the shed
