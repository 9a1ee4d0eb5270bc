; The shed is locked (its door opens onto the patio, where its key lies). One bag of compost, at the rose bed, serves three jobs; one trowel serves three.
(define (problem garden-1)
  (:domain garden)
  (:objects
    human - human
    robot - robot
    shed patio rosebed border - place
    key1 - key
    trowel1 - trowel
    rake1 - rake
    fern1 - fern
    pot1 - pot
    compost1 - compost
    mulch1 - mulch
    rose1 - rose
    tulip1 - tulip
    plant-roses plant-tulips mulch-border repot-fern - job
    red yellow green blue orange - colour
    small large - size
    clay metal wooden - material
  )
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (worksite patio) (worksite rosebed) (worksite border)
    (locked shed) (door shed patio)
    (at human patio)
    (at robot rosebed)
    (in key1 patio) (iscolour key1 yellow) (issize key1 small) (ismaterial key1 metal) (opens key1 shed)
    (in trowel1 shed) (iscolour trowel1 blue) (issize trowel1 small) (ismaterial trowel1 metal)
    (in rake1 shed) (iscolour rake1 green) (issize rake1 large) (ismaterial rake1 wooden)
    (in fern1 patio) (iscolour fern1 green) (issize fern1 small)
    (in pot1 rosebed) (iscolour pot1 orange) (issize pot1 large) (ismaterial pot1 clay)
    (in compost1 rosebed) (issize compost1 large)
    (in mulch1 rosebed) (issize mulch1 small)
    (in rose1 rosebed) (iscolour rose1 red) (issize rose1 large)
    (in tulip1 border) (iscolour tulip1 red) (issize tulip1 small)
    (job-needs plant-roses rose1 compost1 trowel1 rosebed)
    (job-needs plant-tulips tulip1 compost1 trowel1 border)
    (job-needs mulch-border mulch1 compost1 rake1 border)
    (job-needs repot-fern fern1 pot1 trowel1 patio)
  )
  (:goal (done plant-roses))
)
