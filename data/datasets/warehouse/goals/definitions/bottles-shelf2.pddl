(and (on bottle1 shelf2) (on bottle2 shelf2))
