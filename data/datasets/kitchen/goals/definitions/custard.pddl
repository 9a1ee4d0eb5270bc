(made custard)
