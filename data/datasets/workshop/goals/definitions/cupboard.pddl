(made cupboard)
