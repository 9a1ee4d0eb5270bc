; The greenhouse is locked (its door opens onto the border, where its key lies); a fern, herbs and a tulip inside. Two trowels: a small metal one for potting, a large wooden one for the border.
(define (problem garden-7)
  (:domain garden)
  (:objects
    human - human
    robot - robot
    greenhouse shed patio border - place
    key1 - key
    fern1 - fern
    herb1 - herb
    tulip1 - tulip
    trowel1 trowel2 - trowel
    pot1 - pot
    compost1 - compost
    repot-fern pot-herbs plant-ferns plant-herbs plant-tulips - job
    red yellow white green blue orange - colour
    small large - size
    clay metal wooden - material
  )
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (worksite patio) (worksite border)
    (locked greenhouse) (door greenhouse border)
    (at human shed)
    (at robot border)
    (in key1 border) (iscolour key1 yellow) (issize key1 small) (ismaterial key1 metal) (opens key1 greenhouse)
    (in fern1 greenhouse) (iscolour fern1 green) (issize fern1 large)
    (in herb1 greenhouse) (iscolour herb1 green) (issize herb1 small)
    (in tulip1 greenhouse) (iscolour tulip1 white) (issize tulip1 small)
    (in trowel1 shed) (iscolour trowel1 red) (issize trowel1 small) (ismaterial trowel1 metal)
    (in trowel2 shed) (iscolour trowel2 blue) (issize trowel2 large) (ismaterial trowel2 wooden)
    (in pot1 patio) (iscolour pot1 orange) (issize pot1 large) (ismaterial pot1 clay)
    (in compost1 patio) (issize compost1 large)
    (job-needs repot-fern fern1 pot1 trowel1 patio)
    (job-needs pot-herbs herb1 pot1 trowel1 patio)
    (job-needs plant-ferns fern1 compost1 trowel2 border)
    (job-needs plant-herbs herb1 compost1 trowel2 border)
    (job-needs plant-tulips tulip1 compost1 trowel2 border)
  )
  (:goal (done repot-fern))
)
