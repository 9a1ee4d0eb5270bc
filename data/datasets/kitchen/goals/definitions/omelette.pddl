(made omelette)
