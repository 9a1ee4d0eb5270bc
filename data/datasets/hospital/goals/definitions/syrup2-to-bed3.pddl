(on syrup2 bed3)
