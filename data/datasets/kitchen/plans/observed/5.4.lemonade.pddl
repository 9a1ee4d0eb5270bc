(move human counter1 drawer1)
(wait robot)
(open human drawer1)
(wait robot)
(pickup human spoon1 drawer1)
; Scorcher today. Lemonade, I think - mind opening the fridge for me?
