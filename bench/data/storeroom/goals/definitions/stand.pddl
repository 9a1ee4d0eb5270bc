(made stand)
