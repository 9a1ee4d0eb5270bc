(left human c4-7 c3-7)
(wait robot)
(left human c3-7 c2-7)
(wait robot)
(left human c2-7 c1-7)
(wait robot)
(pickup human crate1 c1-7)
; I'm putting the crates away.
