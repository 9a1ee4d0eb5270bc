(on pillow1 bed3)
