(made salsa)
