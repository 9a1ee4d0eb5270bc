(pickup human mulch1 patio)
; Doing the hedge today. Could you bring the rake and the compost down to the gate, please?
