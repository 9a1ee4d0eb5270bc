(holding human inhaler1)
