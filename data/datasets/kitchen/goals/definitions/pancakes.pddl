(made pancakes)
