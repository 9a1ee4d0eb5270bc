(and (on bottle2 shelf2) (on bottle3 shelf2))
