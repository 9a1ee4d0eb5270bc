(done mulch-hedge)
