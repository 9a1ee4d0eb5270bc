(made table)
