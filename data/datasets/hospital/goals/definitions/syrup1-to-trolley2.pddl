(on syrup1 trolley2)
