(done pot-roses)
