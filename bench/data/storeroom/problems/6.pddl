; Nine stations; the robot starts in the garage next to nothing it needs.
(define (problem storeroom-6)
  (:domain storeroom)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins shed loft yard cellar garage - station
    chest locker cupboard - container
    key1 key2 - key
    saw1 - saw
    hammer1 hammer2 - hammer
    screwdriver1 - screwdriver
    plank1 plank2 - plank
    panel1 - panel
    dowel1 - dowel
    bracket1 bracket2 - bracket
    birdhouse shelf frame planter sign - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human bins)
    (at robot garage)
    (stands chest cellar) (locked chest) (fits key1 chest)
    (stands locker shed) (locked locker) (fits key2 locker)
    (stands cupboard yard)
    (in key1 cupboard) (issize key1 small) (ismaterial key1 metal)
    (on key2 toolwall) (issize key2 big) (ismaterial key2 metal)
    (on plank1 rack) (issize plank1 big) (ismaterial plank1 wooden)
    (in plank2 locker) (issize plank2 small) (ismaterial plank2 wooden)
    (in panel1 chest) (issize panel1 big) (ismaterial panel1 wooden)
    (on dowel1 loft) (issize dowel1 small) (ismaterial dowel1 wooden)
    (on bracket1 bins) (issize bracket1 small) (ismaterial bracket1 metal)
    (in bracket2 cupboard) (issize bracket2 big) (ismaterial bracket2 metal)
    (on saw1 toolwall) (issize saw1 big) (ismaterial saw1 metal)
    (on hammer1 toolwall) (issize hammer1 big) (ismaterial hammer1 metal)
    (in hammer2 locker) (issize hammer2 small) (ismaterial hammer2 metal)
    (in screwdriver1 chest) (issize screwdriver1 small) (ismaterial screwdriver1 metal)
    (recipe birdhouse plank2 dowel1 saw1)
    (recipe shelf plank1 bracket1 screwdriver1)
    (recipe frame dowel1 bracket2 hammer1)
    (recipe planter panel1 plank1 hammer2)
    (recipe sign plank2 bracket1 hammer1))
  (:goal (made shelf))
)
