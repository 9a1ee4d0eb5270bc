(done plant-seedlings)
