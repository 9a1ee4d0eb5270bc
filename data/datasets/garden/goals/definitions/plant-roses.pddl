(done plant-roses)
