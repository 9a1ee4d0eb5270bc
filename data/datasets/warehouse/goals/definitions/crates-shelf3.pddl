(and (on crate1 shelf3) (on crate2 shelf3))
