(pickup human basket1 patio)
(wait robot)
(pickup human twine1 patio)
; The roses have gone wild again. You know what to bring.
