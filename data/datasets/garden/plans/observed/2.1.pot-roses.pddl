(pickup human rose1 greenhouse)
; Oh, and could you grab the plastic one for me?
