; Both the shed and the greenhouse are locked; their doors open onto the patio, where both keys lie. Tools are in the shed, a rose and the hose in the greenhouse.
(define (problem garden-4)
  (:domain garden)
  (:objects
    human - human
    robot - robot
    shed greenhouse patio rosebed - place
    key1 key2 - key
    shears1 - shears
    trowel1 - trowel
    rose1 - rose
    hose1 - hose
    basket1 - basket
    fertilizer1 - fertilizer
    twine1 - twine
    pot1 - pot
    prune-roses plant-roses feed-roses pot-roses - job
    red yellow white green blue - colour
    small large - size
    clay plastic metal wooden - material
  )
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (worksite patio) (worksite rosebed)
    (locked shed) (door shed patio)
    (locked greenhouse) (door greenhouse patio)
    (at human rosebed)
    (at robot patio)
    (in key1 patio) (iscolour key1 red) (issize key1 large) (ismaterial key1 metal) (opens key1 shed)
    (in key2 patio) (iscolour key2 blue) (issize key2 small) (ismaterial key2 metal) (opens key2 greenhouse)
    (in shears1 shed) (iscolour shears1 red) (issize shears1 large) (ismaterial shears1 metal)
    (in trowel1 shed) (iscolour trowel1 yellow) (issize trowel1 small) (ismaterial trowel1 metal)
    (in rose1 greenhouse) (iscolour rose1 white) (issize rose1 small)
    (in hose1 greenhouse) (iscolour hose1 green) (issize hose1 large) (ismaterial hose1 plastic)
    (in basket1 patio) (iscolour basket1 yellow) (issize basket1 large) (ismaterial basket1 wooden)
    (in fertilizer1 rosebed) (issize fertilizer1 small)
    (in twine1 rosebed) (iscolour twine1 green) (issize twine1 small)
    (in pot1 patio) (iscolour pot1 blue) (issize pot1 large) (ismaterial pot1 clay)
    (job-needs prune-roses basket1 twine1 shears1 rosebed)
    (job-needs plant-roses rose1 fertilizer1 trowel1 rosebed)
    (job-needs feed-roses fertilizer1 twine1 hose1 rosebed)
    (job-needs pot-roses rose1 pot1 trowel1 patio)
  )
  (:goal (done plant-roses))
)
