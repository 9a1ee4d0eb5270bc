(pickup human seeds1 greenhouse)
; Can you find me something to sow these in? Bring it in here.
