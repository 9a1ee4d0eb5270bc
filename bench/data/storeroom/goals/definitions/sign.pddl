(made sign)
