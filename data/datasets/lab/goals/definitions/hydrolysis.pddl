(done hydrolysis)
