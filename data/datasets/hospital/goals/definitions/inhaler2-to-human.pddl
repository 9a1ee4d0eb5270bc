(holding human inhaler2)
