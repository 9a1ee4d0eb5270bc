(made chair)
