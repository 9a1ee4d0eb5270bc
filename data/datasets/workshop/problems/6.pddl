; Three brackets and two screwdrivers of different sizes and materials.
(define (problem workshop-6)
  (:domain workshop)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins - station
    hammer1 - hammer
    screwdriver1 screwdriver2 - screwdriver
    panel1 panel2 - panel
    bracket1 bracket2 bracket3 - bracket
    shelf cupboard planter frame sign - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human bins)
    (at robot toolwall)
    (on bracket1 bins) (issize bracket1 big) (ismaterial bracket1 metal)
    (on bracket2 bins) (issize bracket2 small) (ismaterial bracket2 metal)
    (on bracket3 bins) (issize bracket3 small) (ismaterial bracket3 wooden)
    (on panel1 rack) (issize panel1 big) (ismaterial panel1 wooden)
    (on panel2 rack) (issize panel2 small) (ismaterial panel2 wooden)
    (on screwdriver1 toolwall) (issize screwdriver1 big) (ismaterial screwdriver1 metal)
    (on screwdriver2 toolwall) (issize screwdriver2 small) (ismaterial screwdriver2 metal)
    (on hammer1 toolwall) (issize hammer1 big) (ismaterial hammer1 wooden)
    (recipe shelf panel1 bracket1 screwdriver1)
    (recipe cupboard panel1 bracket2 screwdriver2)
    (recipe planter panel2 bracket3 hammer1)
    (recipe frame bracket1 bracket2 screwdriver1)
    (recipe sign panel2 bracket3 screwdriver2))
  (:goal (made frame))
)
