(done neutralisation)
