(and (on blanket1 bed3) (on blanket2 bed3))
