(done kinetics)
