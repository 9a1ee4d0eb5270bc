(made stool)
