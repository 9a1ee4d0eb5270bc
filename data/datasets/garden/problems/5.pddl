; No locks. The hedge by the gate and the roses can each be pruned (basket and twine, each with its own shears) or mulched (mulch and compost, with the rake).
(define (problem garden-5)
  (:domain garden)
  (:objects
    human - human
    robot - robot
    shed patio gate rosebed - place
    shears1 shears2 - shears
    rake1 - rake
    twine1 - twine
    basket1 - basket
    compost1 - compost
    mulch1 - mulch
    prune-hedge prune-roses mulch-hedge mulch-roses - job
    red yellow green - colour
    small large - size
    metal wooden - material
  )
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (worksite gate) (worksite rosebed)
    (at human patio)
    (at robot shed)
    (in shears1 shed) (iscolour shears1 red) (issize shears1 large) (ismaterial shears1 metal)
    (in shears2 shed) (iscolour shears2 yellow) (issize shears2 small) (ismaterial shears2 metal)
    (in rake1 shed) (iscolour rake1 green) (issize rake1 large) (ismaterial rake1 wooden)
    (in twine1 patio) (iscolour twine1 green) (issize twine1 small)
    (in basket1 patio) (issize basket1 large) (ismaterial basket1 wooden)
    (in compost1 patio) (issize compost1 large)
    (in mulch1 patio) (issize mulch1 small)
    (job-needs prune-hedge basket1 twine1 shears1 gate)
    (job-needs prune-roses basket1 twine1 shears2 rosebed)
    (job-needs mulch-hedge mulch1 compost1 rake1 gate)
    (job-needs mulch-roses mulch1 compost1 rake1 rosebed)
  )
  (:goal (done prune-hedge))
)
