; Seven stations; the hammer and a panel are in the locked chest (its key on
; the tool wall), a leg in the locked locker (its key in the bins).
(define (problem storeroom-1)
  (:domain storeroom)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins shed loft cellar - station
    chest locker cupboard - container
    key1 key2 - key
    saw1 - saw
    hammer1 - hammer
    screwdriver1 - screwdriver
    plank1 plank2 - plank
    leg1 leg2 - leg
    panel1 - panel
    bracket1 - bracket
    dowel1 - dowel
    shelf table stool crate planter - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human rack)
    (at robot toolwall)
    (stands chest shed) (locked chest) (fits key1 chest)
    (stands locker cellar) (locked locker) (fits key2 locker)
    (stands cupboard loft)
    (on key1 toolwall) (issize key1 small) (ismaterial key1 metal)
    (on key2 bins) (issize key2 big) (ismaterial key2 metal)
    (on plank1 rack) (issize plank1 big) (ismaterial plank1 wooden)
    (in plank2 cupboard) (issize plank2 small) (ismaterial plank2 wooden)
    (on leg1 rack) (issize leg1 big) (ismaterial leg1 wooden)
    (in leg2 locker) (issize leg2 small) (ismaterial leg2 metal)
    (in panel1 chest) (issize panel1 big) (ismaterial panel1 wooden)
    (on bracket1 bins) (issize bracket1 small) (ismaterial bracket1 metal)
    (on dowel1 bins) (issize dowel1 small) (ismaterial dowel1 wooden)
    (on saw1 toolwall) (issize saw1 big) (ismaterial saw1 metal)
    (in hammer1 chest) (issize hammer1 small) (ismaterial hammer1 metal)
    (in screwdriver1 cupboard) (issize screwdriver1 small) (ismaterial screwdriver1 metal)
    (recipe shelf plank1 bracket1 screwdriver1)
    (recipe table plank1 leg1 saw1)
    (recipe stool leg1 dowel1 hammer1)
    (recipe crate panel1 plank2 hammer1)
    (recipe planter leg2 panel1 saw1))
  (:goal (made crate))
)
