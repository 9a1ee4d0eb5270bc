(and (on crate1 shelf1) (on crate3 shelf1))
