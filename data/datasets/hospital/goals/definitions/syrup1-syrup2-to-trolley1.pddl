(and (on syrup1 trolley1) (on syrup2 trolley1))
