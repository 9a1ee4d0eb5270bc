(made compote)
