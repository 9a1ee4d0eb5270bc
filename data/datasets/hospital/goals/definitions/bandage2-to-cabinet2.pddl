(on bandage2 cabinet2)
