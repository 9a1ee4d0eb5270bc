(holding human thermometer2)
