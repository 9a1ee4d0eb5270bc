(and (on box1 shelf3) (on box2 shelf3))
