(on pills2 cabinet3)
