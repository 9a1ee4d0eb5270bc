(on pills1 cabinet3)
