(made pudding)
