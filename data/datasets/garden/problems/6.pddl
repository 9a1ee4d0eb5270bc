; The shed is locked (its door opens onto the vegetable patch, where its key lies). Seedlings to water or plant out, seeds to sow in the greenhouse or the patch.
(define (problem garden-6)
  (:domain garden)
  (:objects
    human - human
    robot - robot
    shed greenhouse vegpatch patio - place
    key1 - key
    hose1 - hose
    spade1 - spade
    trowel1 - trowel
    seedling1 - seedling
    seeds1 - seeds
    tray1 - tray
    fertilizer1 - fertilizer
    compost1 - compost
    water-seedlings plant-seedlings sow-seeds sow-carrots - job
    red white green blue orange - colour
    small large - size
    plastic metal wooden - material
  )
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (worksite greenhouse) (worksite vegpatch)
    (locked shed) (door shed vegpatch)
    (at human greenhouse)
    (at robot vegpatch)
    (in key1 vegpatch) (iscolour key1 white) (issize key1 small) (ismaterial key1 metal) (opens key1 shed)
    (in hose1 shed) (iscolour hose1 green) (issize hose1 large) (ismaterial hose1 plastic)
    (in spade1 shed) (iscolour spade1 blue) (issize spade1 large) (ismaterial spade1 metal)
    (in trowel1 greenhouse) (iscolour trowel1 red) (issize trowel1 small) (ismaterial trowel1 wooden)
    (in seedling1 greenhouse) (iscolour seedling1 green) (issize seedling1 small)
    (in seeds1 greenhouse) (iscolour seeds1 orange) (issize seeds1 small)
    (in tray1 patio) (iscolour tray1 white) (issize tray1 large) (ismaterial tray1 plastic)
    (in fertilizer1 patio) (issize fertilizer1 small)
    (in compost1 patio) (issize compost1 large)
    (job-needs water-seedlings seedling1 fertilizer1 hose1 vegpatch)
    (job-needs plant-seedlings seedling1 compost1 spade1 vegpatch)
    (job-needs sow-seeds seeds1 tray1 trowel1 greenhouse)
    (job-needs sow-carrots seeds1 compost1 trowel1 vegpatch)
  )
  (:goal (done water-seedlings))
)
