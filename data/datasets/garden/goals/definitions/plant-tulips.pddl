(done plant-tulips)
