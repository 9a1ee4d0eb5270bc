(done dissolution)
