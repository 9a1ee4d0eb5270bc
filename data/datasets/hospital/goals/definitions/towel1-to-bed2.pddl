(on towel1 bed2)
