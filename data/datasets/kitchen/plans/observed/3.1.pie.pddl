(pickup human flour1 pantry1)
; Right, I fancy making an apple pie today. Could you give me a hand?
