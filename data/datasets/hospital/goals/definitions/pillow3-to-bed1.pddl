(on pillow3 bed1)
