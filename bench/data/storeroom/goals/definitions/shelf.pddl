(made shelf)
