(holding human pills1)
