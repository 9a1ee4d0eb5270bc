(made cake)
