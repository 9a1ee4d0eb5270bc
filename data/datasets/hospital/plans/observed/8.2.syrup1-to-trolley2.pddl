(move human east-ward lobby)
(wait robot)
(open human lobby storeroom)
(wait robot)
(move human lobby storeroom)
(wait robot)
(pickup human keycard1 storeroom)
; Here, take the card. Could you put the big syrup on trolley number two?
