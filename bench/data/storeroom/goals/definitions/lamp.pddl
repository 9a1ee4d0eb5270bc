(made lamp)
