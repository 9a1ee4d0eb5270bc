(made roast)
