(on blanket1 bed3)
