(done fermentation)
