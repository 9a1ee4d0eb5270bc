(and (on can1 shelf3) (on bottle1 shelf3))
