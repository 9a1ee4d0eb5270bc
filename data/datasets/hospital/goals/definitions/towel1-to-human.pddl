(holding human towel1)
