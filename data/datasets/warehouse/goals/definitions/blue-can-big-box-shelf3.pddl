(and (on can2 shelf3) (on box1 shelf3))
