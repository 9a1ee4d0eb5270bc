(on inhaler1 bed2)
