(on blanket2 bed2)
