(made pie)
