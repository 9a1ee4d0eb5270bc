(made ladder)
