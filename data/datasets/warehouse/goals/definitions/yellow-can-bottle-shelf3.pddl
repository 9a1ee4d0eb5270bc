(and (on can3 shelf3) (on bottle1 shelf3))
