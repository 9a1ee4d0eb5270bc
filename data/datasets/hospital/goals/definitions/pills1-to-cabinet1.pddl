(on pills1 cabinet1)
