(on inhaler2 bed2)
