(move human bench1 shelf1)
; Um, can you get the cells and the big blue bottle from the fridge over to the hotplate?
