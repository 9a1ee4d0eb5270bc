(holding human thermometer1)
