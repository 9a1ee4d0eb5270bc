pick b a
((pick b a))
(pick
