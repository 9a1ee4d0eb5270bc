(and (on jar3 shelf3) (on can1 shelf3))
