; Eight stations; three containers, two of them locked; the human starts in
; the cellar, the robot at the tool wall.
(define (problem storeroom-5)
  (:domain storeroom)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins shed loft yard cellar - station
    chest locker trunk - container
    key1 key2 - key
    drill1 - drill
    wrench1 wrench2 - wrench
    plank1 - plank
    panel1 - panel
    rod1 rod2 - rod
    leg1 leg2 - leg
    bracket1 - bracket
    cart gate stool lamp crate - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human cellar)
    (at robot toolwall)
    (stands chest loft) (locked chest) (fits key1 chest)
    (stands locker yard) (locked locker) (fits key2 locker)
    (stands trunk cellar)
    (on key1 bins) (issize key1 small) (ismaterial key1 metal)
    (in key2 trunk) (issize key2 big) (ismaterial key2 metal)
    (on plank1 rack) (issize plank1 big) (ismaterial plank1 wooden)
    (in panel1 chest) (issize panel1 big) (ismaterial panel1 metal)
    (on rod1 shed) (issize rod1 big) (ismaterial rod1 metal)
    (in rod2 locker) (issize rod2 small) (ismaterial rod2 metal)
    (on leg1 rack) (issize leg1 small) (ismaterial leg1 wooden)
    (in leg2 trunk) (issize leg2 big) (ismaterial leg2 wooden)
    (on bracket1 bins) (issize bracket1 small) (ismaterial bracket1 metal)
    (on drill1 toolwall) (issize drill1 big) (ismaterial drill1 metal)
    (on wrench1 toolwall) (issize wrench1 small) (ismaterial wrench1 metal)
    (in wrench2 locker) (issize wrench2 big) (ismaterial wrench2 metal)
    (recipe cart panel1 rod1 wrench1)
    (recipe gate plank1 rod2 drill1)
    (recipe stool leg1 leg2 wrench2)
    (recipe lamp rod1 bracket1 drill1)
    (recipe crate plank1 panel1 wrench2))
  (:goal (made gate))
)
