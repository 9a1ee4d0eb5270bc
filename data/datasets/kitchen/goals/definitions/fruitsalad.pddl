(made fruitsalad)
