(done extraction)
