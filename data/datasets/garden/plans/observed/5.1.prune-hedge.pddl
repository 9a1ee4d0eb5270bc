(pickup human basket1 patio)
; Can you get the large shears for me?
