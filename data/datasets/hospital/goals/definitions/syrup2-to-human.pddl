(holding human syrup2)
