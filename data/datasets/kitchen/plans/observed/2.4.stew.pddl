(move human counter1 pantry1)
(wait robot)
(pickup human onion1 pantry1)
; Stew tonight, I reckon. Could you sort the rest while I get the potato?
