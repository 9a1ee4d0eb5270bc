(done standardisation)
