(and (on bag1 shelf2) (on bag2 shelf2))
