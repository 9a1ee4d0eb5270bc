(and (on jar2 shelf2) (on box2 shelf2))
