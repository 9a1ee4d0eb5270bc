(move human counter1 cupboard1)
(wait robot)
(pickup human tray1 cupboard1)
; Could you grab me a potatoe and an onion?
