; The shed is locked (its door opens onto the patio, where its key lies). A red rose, a red tulip and a yellow tulip by the gate; two pots on the patio.
(define (problem garden-8)
  (:domain garden)
  (:objects
    human - human
    robot - robot
    shed patio gate border - place
    key1 - key
    trowel1 - trowel
    spade1 - spade
    compost1 - compost
    rose1 - rose
    tulip1 tulip2 - tulip
    pot1 pot2 - pot
    plant-roses pot-roses plant-tulips pot-tulips - job
    red yellow green orange - colour
    small large - size
    clay plastic metal wooden - material
  )
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (worksite patio) (worksite border)
    (locked shed) (door shed patio)
    (at human gate)
    (at robot patio)
    (in key1 patio) (iscolour key1 orange) (issize key1 small) (ismaterial key1 metal) (opens key1 shed)
    (in trowel1 shed) (iscolour trowel1 green) (issize trowel1 small) (ismaterial trowel1 metal)
    (in spade1 shed) (iscolour spade1 red) (issize spade1 large) (ismaterial spade1 wooden)
    (in compost1 shed) (issize compost1 large)
    (in rose1 gate) (iscolour rose1 red) (issize rose1 large)
    (in tulip1 gate) (iscolour tulip1 red) (issize tulip1 small)
    (in tulip2 gate) (iscolour tulip2 yellow) (issize tulip2 small)
    (in pot1 patio) (iscolour pot1 green) (issize pot1 small) (ismaterial pot1 plastic)
    (in pot2 patio) (iscolour pot2 red) (issize pot2 large) (ismaterial pot2 clay)
    (job-needs plant-roses rose1 compost1 spade1 border)
    (job-needs pot-roses rose1 pot2 trowel1 patio)
    (job-needs plant-tulips tulip2 compost1 trowel1 border)
    (job-needs pot-tulips tulip1 pot1 trowel1 patio)
  )
  (:goal (done plant-roses))
)
