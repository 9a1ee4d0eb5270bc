(and (on bottle1 shelf1) (on bottle2 shelf1))
