(and (on bottle1 shelf2) (on can2 shelf2))
