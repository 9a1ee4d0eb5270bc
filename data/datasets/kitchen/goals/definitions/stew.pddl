(made stew)
