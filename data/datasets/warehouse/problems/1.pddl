; Two racks; three cans and a bag along the top aisle, two boxes along the bottom one. Shelf 1 and shelf 2 stand against the side walls of the middle aisle, shelf 3 at the bottom.
; Map (x grows to the right, y downwards; cell cX-Y; # wall, digits: shelves,
;      letters: items, H / R: where the human / robot start):
;   #########
;   #a.b.c.f#
;   #.##.##.#
;   #.##.##.#
;   1...H...2
;   #.##.##.#
;   #d..R..e#
;   ####3####
;   items: a=can1 (small red can), b=can2 (small blue can), c=can3 (small green can), f=bag1 (small blue bag), d=box1 (large yellow box), e=box2 (small white box)
(define (problem warehouse-1)
  (:domain warehouse)
  (:objects
    human - human
    robot - robot
    c1-1 c2-1 c3-1 c4-1 c5-1 c6-1 c7-1 c1-2 c4-2 c7-2
    c1-3 c4-3 c7-3 c1-4 c2-4 c3-4 c4-4 c5-4 c6-4 c7-4
    c1-5 c4-5 c7-5 c1-6 c2-6 c3-6 c4-6 c5-6 c6-6 c7-6 - cell
    shelf1 shelf2 shelf3 - shelf
    bag1 - bag
    box1 box2 - box
    can1 can2 can3 - can
    blue green red white yellow - colour
    large small - size
  )
  (:init
    (at human c4-4) (at robot c4-6)
    (lies bag1 c7-1) (iscolour bag1 blue) (issize bag1 small)
    (lies box1 c1-6) (iscolour box1 yellow) (issize box1 large)
    (lies box2 c7-6) (iscolour box2 white) (issize box2 small)
    (lies can1 c1-1) (iscolour can1 red) (issize can1 small)
    (lies can2 c3-1) (iscolour can2 blue) (issize can2 small)
    (lies can3 c5-1) (iscolour can3 green) (issize can3 small)
    (reaches c1-4 shelf1)
    (reaches c7-4 shelf2)
    (reaches c4-6 shelf3)
    (step-up c1-2 c1-1) (step-up c4-2 c4-1) (step-up c7-2 c7-1) (step-up c1-3 c1-2) (step-up c4-3 c4-2) (step-up c7-3 c7-2)
    (step-up c1-4 c1-3) (step-up c4-4 c4-3) (step-up c7-4 c7-3) (step-up c1-5 c1-4) (step-up c4-5 c4-4) (step-up c7-5 c7-4)
    (step-up c1-6 c1-5) (step-up c4-6 c4-5) (step-up c7-6 c7-5)
    (step-down c1-1 c1-2) (step-down c4-1 c4-2) (step-down c7-1 c7-2) (step-down c1-2 c1-3) (step-down c4-2 c4-3) (step-down c7-2 c7-3)
    (step-down c1-3 c1-4) (step-down c4-3 c4-4) (step-down c7-3 c7-4) (step-down c1-4 c1-5) (step-down c4-4 c4-5) (step-down c7-4 c7-5)
    (step-down c1-5 c1-6) (step-down c4-5 c4-6) (step-down c7-5 c7-6)
    (step-left c2-1 c1-1) (step-left c3-1 c2-1) (step-left c4-1 c3-1) (step-left c5-1 c4-1) (step-left c6-1 c5-1) (step-left c7-1 c6-1)
    (step-left c2-4 c1-4) (step-left c3-4 c2-4) (step-left c4-4 c3-4) (step-left c5-4 c4-4) (step-left c6-4 c5-4) (step-left c7-4 c6-4)
    (step-left c2-6 c1-6) (step-left c3-6 c2-6) (step-left c4-6 c3-6) (step-left c5-6 c4-6) (step-left c6-6 c5-6) (step-left c7-6 c6-6)
    (step-right c1-1 c2-1) (step-right c2-1 c3-1) (step-right c3-1 c4-1) (step-right c4-1 c5-1) (step-right c5-1 c6-1) (step-right c6-1 c7-1)
    (step-right c1-4 c2-4) (step-right c2-4 c3-4) (step-right c3-4 c4-4) (step-right c4-4 c5-4) (step-right c5-4 c6-4) (step-right c6-4 c7-4)
    (step-right c1-6 c2-6) (step-right c2-6 c3-6) (step-right c3-6 c4-6) (step-right c4-6 c5-6) (step-right c5-6 c6-6) (step-right c6-6 c7-6)
  )
  (:goal (and (on can1 shelf1) (on can2 shelf1)))
)
