(and (on crate1 shelf1) (on bottle3 shelf1))
