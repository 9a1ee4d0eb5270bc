(made sauce)
