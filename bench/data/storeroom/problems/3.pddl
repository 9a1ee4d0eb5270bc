; Nine stations; two locked containers and a closed cupboard; both agents
; start at the bench.
(define (problem storeroom-3)
  (:domain storeroom)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins shed loft yard cellar garage - station
    chest locker cupboard - container
    key1 key2 - key
    saw1 saw2 - saw
    hammer1 - hammer
    plank1 plank2 - plank
    dowel1 dowel2 - dowel
    leg1 - leg
    bracket1 bracket2 - bracket
    ladder frame birdhouse sign bookcase - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human bench)
    (at robot bench)
    (stands chest garage) (locked chest) (fits key1 chest)
    (stands locker cellar) (locked locker) (fits key2 locker)
    (stands cupboard loft)
    (on key1 shed) (issize key1 small) (ismaterial key1 metal)
    (in key2 cupboard) (issize key2 big) (ismaterial key2 metal)
    (on plank1 rack) (issize plank1 big) (ismaterial plank1 wooden)
    (in plank2 chest) (issize plank2 small) (ismaterial plank2 wooden)
    (on dowel1 rack) (issize dowel1 small) (ismaterial dowel1 wooden)
    (in dowel2 locker) (issize dowel2 big) (ismaterial dowel2 wooden)
    (on leg1 yard) (issize leg1 big) (ismaterial leg1 wooden)
    (on bracket1 bins) (issize bracket1 small) (ismaterial bracket1 metal)
    (in bracket2 chest) (issize bracket2 big) (ismaterial bracket2 metal)
    (on saw1 toolwall) (issize saw1 big) (ismaterial saw1 metal)
    (in saw2 locker) (issize saw2 small) (ismaterial saw2 metal)
    (on hammer1 toolwall) (issize hammer1 small) (ismaterial hammer1 metal)
    (recipe ladder plank1 dowel2 saw1)
    (recipe frame dowel1 bracket2 hammer1)
    (recipe birdhouse plank2 dowel1 saw2)
    (recipe sign plank1 bracket1 hammer1)
    (recipe bookcase leg1 plank2 saw1))
  (:goal (made ladder))
)
