(pickup human seedling1 greenhouse)
; So I'm planting these out in the veg patch today, been meaning to for ages. Could you get what I need from the shed?
