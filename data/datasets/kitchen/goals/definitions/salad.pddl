(made salad)
