; Two planks of different sizes share a leg and a bracket; a hammer and a screwdriver.
(define (problem workshop-1)
  (:domain workshop)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins - station
    hammer1 - hammer
    screwdriver1 - screwdriver
    plank1 plank2 - plank
    leg1 - leg
    bracket1 - bracket
    stool table shelf birdhouse - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human bench)
    (at robot bench)
    (on plank1 rack) (issize plank1 big) (ismaterial plank1 wooden)
    (on plank2 rack) (issize plank2 small) (ismaterial plank2 wooden)
    (on leg1 rack) (issize leg1 small) (ismaterial leg1 wooden)
    (on bracket1 bins) (issize bracket1 small) (ismaterial bracket1 metal)
    (on hammer1 toolwall) (issize hammer1 big) (ismaterial hammer1 metal)
    (on screwdriver1 toolwall) (issize screwdriver1 small) (ismaterial screwdriver1 metal)
    (recipe stool plank2 leg1 hammer1)
    (recipe table plank1 leg1 hammer1)
    (recipe shelf plank1 bracket1 screwdriver1)
    (recipe birdhouse plank2 bracket1 screwdriver1))
  (:goal (made table))
)
