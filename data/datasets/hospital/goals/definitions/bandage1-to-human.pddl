(holding human bandage1)
