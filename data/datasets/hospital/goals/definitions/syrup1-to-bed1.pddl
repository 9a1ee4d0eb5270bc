(on syrup1 bed1)
