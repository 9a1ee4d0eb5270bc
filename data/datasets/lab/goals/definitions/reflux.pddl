(done reflux)
