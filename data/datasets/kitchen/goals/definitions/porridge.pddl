(made porridge)
