(on pills2 cabinet1)
