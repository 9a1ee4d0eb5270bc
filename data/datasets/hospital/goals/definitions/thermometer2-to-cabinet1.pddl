(on thermometer2 cabinet1)
