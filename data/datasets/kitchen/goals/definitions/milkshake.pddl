(made milkshake)
