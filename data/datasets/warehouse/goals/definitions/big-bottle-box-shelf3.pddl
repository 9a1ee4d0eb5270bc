(and (on bottle1 shelf3) (on box1 shelf3))
