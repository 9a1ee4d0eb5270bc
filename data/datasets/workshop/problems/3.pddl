; Two saws and two dowels of different sizes; the human starts at the rack, the robot at the tool wall.
(define (problem workshop-3)
  (:domain workshop)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins - station
    saw1 saw2 - saw
    screwdriver1 - screwdriver
    plank1 plank2 - plank
    bracket2 - bracket
    dowel1 dowel2 - dowel
    frame ladder birdhouse sign - product
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
    (on dowel1 rack) (issize dowel1 small) (ismaterial dowel1 wooden)
    (on dowel2 rack) (issize dowel2 big) (ismaterial dowel2 wooden)
    (on bracket2 bins) (issize bracket2 small) (ismaterial bracket2 metal)
    (on saw1 toolwall) (issize saw1 big) (ismaterial saw1 metal)
    (on saw2 toolwall) (issize saw2 small) (ismaterial saw2 metal)
    (on screwdriver1 toolwall) (issize screwdriver1 small) (ismaterial screwdriver1 metal)
    (recipe frame dowel2 bracket2 screwdriver1)
    (recipe ladder dowel2 plank1 saw1)
    (recipe birdhouse plank2 dowel1 saw2)
    (recipe sign plank2 bracket2 screwdriver1))
  (:goal (made ladder))
)
