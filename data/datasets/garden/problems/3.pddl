; The greenhouse is locked (its door opens onto the patio, where its key lies); a tulip and some herbs inside, to be planted in the border or potted.
(define (problem garden-3)
  (:domain garden)
  (:objects
    human - human
    robot - robot
    greenhouse shed patio border - place
    key1 - key
    tulip1 - tulip
    herb1 - herb
    trowel1 - trowel
    compost1 - compost
    pot1 pot2 - pot
    plant-tulips pot-tulips plant-herbs pot-herbs - job
    red yellow white green orange - colour
    small large - size
    clay plastic metal - material
  )
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (worksite patio) (worksite border)
    (locked greenhouse) (door greenhouse patio)
    (at human shed)
    (at robot patio)
    (in key1 patio) (iscolour key1 green) (issize key1 small) (ismaterial key1 metal) (opens key1 greenhouse)
    (in tulip1 greenhouse) (iscolour tulip1 yellow) (issize tulip1 small)
    (in herb1 greenhouse) (iscolour herb1 green) (issize herb1 large)
    (in trowel1 shed) (iscolour trowel1 orange) (issize trowel1 small) (ismaterial trowel1 metal)
    (in compost1 shed) (issize compost1 large)
    (in pot1 shed) (iscolour pot1 red) (issize pot1 small) (ismaterial pot1 clay)
    (in pot2 patio) (iscolour pot2 white) (issize pot2 large) (ismaterial pot2 plastic)
    (job-needs plant-tulips tulip1 compost1 trowel1 border)
    (job-needs pot-tulips tulip1 pot1 trowel1 patio)
    (job-needs plant-herbs herb1 compost1 trowel1 border)
    (job-needs pot-herbs herb1 pot2 trowel1 patio)
  )
  (:goal (done plant-tulips))
)
