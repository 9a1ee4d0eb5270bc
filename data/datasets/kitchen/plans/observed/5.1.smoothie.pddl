(move human counter1 drawer1)
(wait robot)
(open human drawer1)
(wait robot)
(pickup human spoon1 drawer1)
; Could you fetch the milk from the fridge, please? I'll sort out the fruit.
