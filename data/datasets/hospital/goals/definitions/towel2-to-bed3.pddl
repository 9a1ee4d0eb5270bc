(on towel2 bed3)
