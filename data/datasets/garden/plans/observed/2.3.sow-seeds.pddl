(move human greenhouse patio)
(wait robot)
(pickup human seeds1 patio)
; I need a tray and the trowel. Um, they should both be in the shed.
