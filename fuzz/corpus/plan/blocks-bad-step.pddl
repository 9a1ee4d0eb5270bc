(pick a table)
(place a b)
