(done prune-roses)
