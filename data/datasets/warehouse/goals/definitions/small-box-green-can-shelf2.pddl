(and (on box2 shelf2) (on can3 shelf2))
