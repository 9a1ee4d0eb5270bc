(pickup human seedling1 greenhouse)
; I'll need something to water these with. Can you get it out of the shed?
