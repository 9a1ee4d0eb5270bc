(on syrup1 trolley1)
