; Wooden and metal parts; the robot starts beside the tools, the human at the rack.
(define (problem workshop-2)
  (:domain workshop)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins - station
    hammer1 - hammer
    wrench1 - wrench
    drill1 - drill
    panel1 panel2 - panel
    leg1 leg2 - leg
    rod1 - rod
    bracket1 - bracket
    cart table lamp crate stand - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human rack)
    (at robot toolwall)
    (on panel1 rack) (issize panel1 big) (ismaterial panel1 wooden)
    (on panel2 rack) (issize panel2 small) (ismaterial panel2 metal)
    (on rod1 rack) (issize rod1 big) (ismaterial rod1 metal)
    (on leg1 bins) (issize leg1 small) (ismaterial leg1 wooden)
    (on leg2 bins) (issize leg2 small) (ismaterial leg2 metal)
    (on bracket1 bins) (issize bracket1 small) (ismaterial bracket1 metal)
    (on wrench1 toolwall) (issize wrench1 small) (ismaterial wrench1 metal)
    (on hammer1 toolwall) (issize hammer1 big) (ismaterial hammer1 wooden)
    (on drill1 toolwall) (issize drill1 big) (ismaterial drill1 metal)
    (recipe cart panel2 leg2 wrench1)
    (recipe table panel1 leg1 hammer1)
    (recipe lamp rod1 bracket1 wrench1)
    (recipe crate panel1 panel2 drill1)
    (recipe stand rod1 leg1 hammer1))
  (:goal (made cart))
)
