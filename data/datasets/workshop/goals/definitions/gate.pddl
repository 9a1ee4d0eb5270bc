(made gate)
