(pickup human rose1 gate)
; can u unlock the shed and hand me the little one
