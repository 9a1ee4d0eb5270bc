(done incubation)
