(done water-seedlings)
