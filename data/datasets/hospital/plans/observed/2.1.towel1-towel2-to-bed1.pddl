(move human west-ward reception)
(wait robot)
(open human reception laundry)
(wait robot)
(move human reception laundry)
(wait robot)
(pickup human towel1 laundry)
; Can you bring me another one of these?
