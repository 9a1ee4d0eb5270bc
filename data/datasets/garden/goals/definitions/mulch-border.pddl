(done mulch-border)
