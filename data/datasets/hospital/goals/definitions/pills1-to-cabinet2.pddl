(on pills1 cabinet2)
