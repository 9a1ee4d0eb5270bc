(and (on box1 shelf3) (on can1 shelf3))
