(on bandage1 bed1)
