(done titration)
