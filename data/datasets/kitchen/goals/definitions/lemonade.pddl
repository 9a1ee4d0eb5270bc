(made lemonade)
