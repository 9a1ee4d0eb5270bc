(fly a)
(pick a b c)
(pick zz table)
