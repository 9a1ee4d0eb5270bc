(done plant-ferns)
