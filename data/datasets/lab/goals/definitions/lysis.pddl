(done lysis)
