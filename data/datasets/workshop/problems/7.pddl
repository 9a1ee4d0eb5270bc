; Three legs; the human starts at the tool wall, the robot at the rack.
(define (problem workshop-7)
  (:domain workshop)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins - station
    hammer1 - hammer
    drill1 - drill
    plank1 - plank
    panel1 - panel
    leg1 leg2 leg3 - leg
    dowel1 - dowel
    table stool chair stand - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human toolwall)
    (at robot rack)
    (on leg1 rack) (issize leg1 big) (ismaterial leg1 wooden)
    (on leg2 rack) (issize leg2 small) (ismaterial leg2 wooden)
    (on leg3 rack) (issize leg3 small) (ismaterial leg3 metal)
    (on plank1 rack) (issize plank1 small) (ismaterial plank1 wooden)
    (on panel1 bins) (issize panel1 small) (ismaterial panel1 metal)
    (on dowel1 bins) (issize dowel1 small) (ismaterial dowel1 wooden)
    (on hammer1 toolwall) (issize hammer1 big) (ismaterial hammer1 metal)
    (on drill1 toolwall) (issize drill1 small) (ismaterial drill1 metal)
    (recipe table plank1 leg1 hammer1)
    (recipe stool plank1 leg2 drill1)
    (recipe chair panel1 leg3 drill1)
    (recipe stand dowel1 leg2 hammer1))
  (:goal (made stool))
)
