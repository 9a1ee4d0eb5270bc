; No locks. A rose and a fern, each to be planted in the border or potted on the patio; seeds to sow in a tray in the greenhouse.
(define (problem garden-2)
  (:domain garden)
  (:objects
    human - human
    robot - robot
    shed greenhouse patio border - place
    rose1 - rose
    fern1 - fern
    trowel1 - trowel
    spade1 - spade
    compost1 - compost
    pot1 pot2 - pot
    tray1 - tray
    seeds1 - seeds
    plant-roses pot-roses plant-ferns repot-fern sow-seeds - job
    red yellow pink green blue orange - colour
    small large - size
    clay plastic metal wooden - material
  )
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (worksite greenhouse) (worksite patio) (worksite border)
    (at human greenhouse)
    (at robot shed)
    (in rose1 greenhouse) (iscolour rose1 pink) (issize rose1 small)
    (in fern1 greenhouse) (iscolour fern1 green) (issize fern1 large)
    (in trowel1 shed) (iscolour trowel1 red) (issize trowel1 small) (ismaterial trowel1 metal)
    (in spade1 shed) (iscolour spade1 blue) (issize spade1 large) (ismaterial spade1 wooden)
    (in compost1 shed) (issize compost1 large)
    (in pot1 shed) (iscolour pot1 orange) (issize pot1 large) (ismaterial pot1 clay)
    (in pot2 shed) (iscolour pot2 blue) (issize pot2 small) (ismaterial pot2 plastic)
    (in tray1 shed) (iscolour tray1 green) (issize tray1 large) (ismaterial tray1 plastic)
    (in seeds1 patio) (iscolour seeds1 yellow) (issize seeds1 small)
    (job-needs plant-roses rose1 compost1 spade1 border)
    (job-needs pot-roses rose1 pot2 trowel1 patio)
    (job-needs plant-ferns fern1 compost1 spade1 border)
    (job-needs repot-fern fern1 pot1 trowel1 patio)
    (job-needs sow-seeds seeds1 tray1 trowel1 greenhouse)
  )
  (:goal (done pot-roses))
)
