; Five stations; five candidate products.
(define (problem workshop-8)
  (:domain workshop)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins cabinet - station
    saw1 - saw
    wrench1 - wrench
    drill1 - drill
    plank1 plank2 - plank
    leg1 - leg
    rod1 - rod
    dowel1 - dowel
    gate birdhouse sign cart stool - product
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
    (on rod1 rack) (issize rod1 big) (ismaterial rod1 metal)
    (on dowel1 bins) (issize dowel1 small) (ismaterial dowel1 wooden)
    (on leg1 bins) (issize leg1 big) (ismaterial leg1 metal)
    (on saw1 toolwall) (issize saw1 big) (ismaterial saw1 metal)
    (on drill1 cabinet) (issize drill1 big) (ismaterial drill1 metal)
    (on wrench1 cabinet) (issize wrench1 small) (ismaterial wrench1 metal)
    (recipe gate plank1 rod1 drill1)
    (recipe birdhouse plank2 dowel1 saw1)
    (recipe sign plank1 dowel1 saw1)
    (recipe cart rod1 leg1 wrench1)
    (recipe stool plank2 leg1 drill1))
  (:goal (made gate))
)
