(done plant-herbs)
