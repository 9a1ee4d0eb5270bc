(on blanket1 bed2)
