(pickup human rose1 gate)
; This one's for the border. Can you get the shovel out of the shed for me?
