(and (on crate2 shelf2) (on bag2 shelf2))
