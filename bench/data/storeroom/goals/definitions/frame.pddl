(made frame)
