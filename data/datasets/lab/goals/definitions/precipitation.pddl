(done precipitation)
