(and (on box2 shelf4) (on can2 shelf4))
