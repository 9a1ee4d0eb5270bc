; Eight stations; the drill is in the locked locker, whose key is in the
; (unlocked) trunk in the yard; the chest's key lies on the rack.
(define (problem storeroom-2)
  (:domain storeroom)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins shed loft yard cellar - station
    chest locker trunk - container
    key1 key2 - key
    saw1 - saw
    drill1 - drill
    wrench1 - wrench
    plank1 - plank
    rod1 rod2 - rod
    leg1 - leg
    panel1 panel2 - panel
    bracket1 - bracket
    gate cart lamp desk stand - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human bench)
    (at robot yard)
    (stands chest shed) (locked chest) (fits key1 chest)
    (stands locker cellar) (locked locker) (fits key2 locker)
    (stands trunk yard)
    (on key1 rack) (issize key1 small) (ismaterial key1 metal)
    (in key2 trunk) (issize key2 small) (ismaterial key2 metal)
    (on plank1 rack) (issize plank1 big) (ismaterial plank1 wooden)
    (on rod1 rack) (issize rod1 big) (ismaterial rod1 metal)
    (in rod2 chest) (issize rod2 small) (ismaterial rod2 metal)
    (on leg1 loft) (issize leg1 big) (ismaterial leg1 wooden)
    (in panel1 trunk) (issize panel1 big) (ismaterial panel1 wooden)
    (in panel2 chest) (issize panel2 small) (ismaterial panel2 metal)
    (on bracket1 bins) (issize bracket1 small) (ismaterial bracket1 metal)
    (on saw1 toolwall) (issize saw1 big) (ismaterial saw1 metal)
    (in drill1 locker) (issize drill1 small) (ismaterial drill1 metal)
    (on wrench1 toolwall) (issize wrench1 big) (ismaterial wrench1 metal)
    (recipe gate plank1 rod1 saw1)
    (recipe cart panel1 rod2 wrench1)
    (recipe lamp rod1 bracket1 drill1)
    (recipe desk panel1 leg1 saw1)
    (recipe stand leg1 panel2 wrench1))
  (:goal (made cart))
)
