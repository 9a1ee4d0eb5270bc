(and (on jar1 shelf1) (on jar2 shelf1))
