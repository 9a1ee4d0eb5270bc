(made toolbox)
