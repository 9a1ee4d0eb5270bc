(and (on box1 shelf2) (on box2 shelf2))
