(made planter)
