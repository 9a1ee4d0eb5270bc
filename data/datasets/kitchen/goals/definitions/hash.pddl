(made hash)
