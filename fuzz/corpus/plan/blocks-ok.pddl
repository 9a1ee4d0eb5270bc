(pick b a)
; put it on the table please
(place b table)
(pick a table)

(place a b)
