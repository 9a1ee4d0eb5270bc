(made meringue)
