; Six stations; one locked chest whose key is in the closed cupboard.
(define (problem storeroom-4)
  (:domain storeroom)
  (:objects
    human - human
    robot - robot
    bench rack toolwall bins shed loft - station
    chest cupboard - container
    key1 key2 - key
    hammer1 - hammer
    screwdriver1 screwdriver2 - screwdriver
    panel1 panel2 - panel
    leg1 leg2 - leg
    rod1 - rod
    dowel1 - dowel
    toolbox chair table shelf trellis - product
    big small - size
    wooden metal - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (workbench bench)
    (at human toolwall)
    (at robot bench)
    (stands chest shed) (locked chest) (fits key1 chest)
    (stands cupboard loft)
    (in key1 cupboard) (issize key1 small) (ismaterial key1 metal)
    (on key2 bins) (issize key2 big) (ismaterial key2 metal)
    (on panel1 rack) (issize panel1 big) (ismaterial panel1 wooden)
    (in panel2 chest) (issize panel2 small) (ismaterial panel2 metal)
    (on leg1 rack) (issize leg1 big) (ismaterial leg1 wooden)
    (in leg2 chest) (issize leg2 small) (ismaterial leg2 wooden)
    (on rod1 bins) (issize rod1 small) (ismaterial rod1 metal)
    (in dowel1 cupboard) (issize dowel1 big) (ismaterial dowel1 wooden)
    (on hammer1 toolwall) (issize hammer1 big) (ismaterial hammer1 metal)
    (on screwdriver1 toolwall) (issize screwdriver1 big) (ismaterial screwdriver1 metal)
    (in screwdriver2 chest) (issize screwdriver2 small) (ismaterial screwdriver2 metal)
    (recipe toolbox panel2 rod1 screwdriver1)
    (recipe chair leg1 leg2 hammer1)
    (recipe table panel1 leg1 hammer1)
    (recipe shelf panel1 dowel1 screwdriver2)
    (recipe trellis rod1 dowel1 hammer1))
  (:goal (made chair))
)
