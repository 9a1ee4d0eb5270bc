(and (on jar2 shelf3) (on bag2 shelf3))
