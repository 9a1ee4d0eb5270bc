(done prune-hedge)
