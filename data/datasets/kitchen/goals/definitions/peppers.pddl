(made peppers)
