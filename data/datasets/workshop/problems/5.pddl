; Three stations: planks and rods of two sizes at the rack.
(define (problem workshop-5)
  (:domain workshop)
  (:objects
    human - human
    robot - robot
    bench rack toolwall - station
    hammer1 - hammer
    saw1 - saw
    wrench1 - wrench
    plank1 plank2 - plank
    rod1 rod2 - rod
    trellis bookcase sign ladder - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human rack)
    (at robot toolwall)
    (on plank1 rack) (issize plank1 big) (ismaterial plank1 wooden)
    (on plank2 rack) (issize plank2 small) (ismaterial plank2 wooden)
    (on rod1 rack) (issize rod1 big) (ismaterial rod1 metal)
    (on rod2 rack) (issize rod2 small) (ismaterial rod2 metal)
    (on saw1 toolwall) (issize saw1 big) (ismaterial saw1 metal)
    (on hammer1 toolwall) (issize hammer1 small) (ismaterial hammer1 wooden)
    (on wrench1 toolwall) (issize wrench1 small) (ismaterial wrench1 metal)
    (recipe trellis rod1 rod2 wrench1)
    (recipe bookcase plank1 plank2 hammer1)
    (recipe sign plank2 rod2 saw1)
    (recipe ladder plank1 rod1 saw1))
  (:goal (made ladder))
)
