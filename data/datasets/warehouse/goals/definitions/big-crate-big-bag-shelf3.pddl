(and (on crate1 shelf3) (on bag1 shelf3))
