(and (on towel1 bed2) (on towel2 bed2))
