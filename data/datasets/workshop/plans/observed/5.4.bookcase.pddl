(pickup human plank2 rack)
; Could you pass me a tool for driving nails?
