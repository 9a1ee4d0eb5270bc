(and (on can1 shelf1) (on can2 shelf1))
