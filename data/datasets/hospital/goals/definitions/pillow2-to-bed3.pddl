(on pillow2 bed3)
