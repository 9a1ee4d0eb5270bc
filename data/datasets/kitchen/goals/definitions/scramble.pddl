(made scramble)
