(and (on bag1 shelf3) (on bag3 shelf3))
