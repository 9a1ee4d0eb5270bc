(and (on towel1 bed1) (on towel2 bed1))
