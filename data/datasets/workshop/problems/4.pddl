; Two drills of different sizes on the tool wall, where the human starts.
(define (problem workshop-4)
  (:domain workshop)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins - station
    wrench1 - wrench
    drill1 drill2 - drill
    panel1 panel2 - panel
    leg1 - leg
    rod1 - rod
    bracket1 - bracket
    desk toolbox crate cart - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human toolwall)
    (at robot bench)
    (on panel1 rack) (issize panel1 big) (ismaterial panel1 wooden)
    (on panel2 rack) (issize panel2 big) (ismaterial panel2 metal)
    (on rod1 rack) (issize rod1 small) (ismaterial rod1 metal)
    (on leg1 bins) (issize leg1 big) (ismaterial leg1 wooden)
    (on bracket1 bins) (issize bracket1 small) (ismaterial bracket1 metal)
    (on drill1 toolwall) (issize drill1 small) (ismaterial drill1 metal)
    (on drill2 toolwall) (issize drill2 big) (ismaterial drill2 metal)
    (on wrench1 toolwall) (issize wrench1 big) (ismaterial wrench1 metal)
    (recipe desk panel1 leg1 drill2)
    (recipe toolbox panel2 bracket1 drill1)
    (recipe crate panel1 bracket1 drill1)
    (recipe cart panel2 rod1 wrench1))
  (:goal (made desk))
)
