(done mulch-roses)
