(and (on can1 shelf1) (on box1 shelf1))
