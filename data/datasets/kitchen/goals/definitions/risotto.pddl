(made risotto)
