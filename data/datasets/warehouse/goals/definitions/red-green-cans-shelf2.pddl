(and (on can1 shelf2) (on can3 shelf2))
