(made cart)
