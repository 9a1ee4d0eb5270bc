(and (on box3 shelf4) (on can1 shelf4))
