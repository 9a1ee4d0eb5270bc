(done dilution)
