(made desk)
