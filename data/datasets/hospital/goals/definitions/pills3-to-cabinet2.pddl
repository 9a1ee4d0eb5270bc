(on pills3 cabinet2)
