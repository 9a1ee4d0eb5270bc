(on splint1 bed3)
