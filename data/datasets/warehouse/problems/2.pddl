; Crates on the left, bottles on the right, a jar and a box in the bottom room. Two of the goals are orders the human carries away by hand (the human ends holding both items).
; Map (x grows to the right, y downwards; cell cX-Y; # wall, digits: shelves,
;      letters: items, H / R: where the human / robot start):
;   ###2#####
;   #a..R..c#
;   #.##.##.#
;   #b##.##d#
;   #...H...#
;   ####.####
;   #e.....f#
;   ###1#3###
;   items: a=crate1 (large red crate), c=bottle1 (large green bottle), b=crate2 (large blue crate), d=bottle2 (small green bottle), e=jar1 (small white jar), f=box1 (small yellow box)
(define (problem warehouse-2)
  (:domain warehouse)
  (:objects
    human - human
    robot - robot
    c1-1 c2-1 c3-1 c4-1 c5-1 c6-1 c7-1 c1-2 c4-2 c7-2
    c1-3 c4-3 c7-3 c1-4 c2-4 c3-4 c4-4 c5-4 c6-4 c7-4
    c4-5 c1-6 c2-6 c3-6 c4-6 c5-6 c6-6 c7-6 - cell
    shelf1 shelf2 shelf3 - shelf
    bottle1 bottle2 - bottle
    box1 - box
    crate1 crate2 - crate
    jar1 - jar
    blue green red white yellow - colour
    large small - size
  )
  (:init
    (at human c4-4) (at robot c4-1)
    (lies bottle1 c7-1) (iscolour bottle1 green) (issize bottle1 large)
    (lies bottle2 c7-3) (iscolour bottle2 green) (issize bottle2 small)
    (lies box1 c7-6) (iscolour box1 yellow) (issize box1 small)
    (lies crate1 c1-1) (iscolour crate1 red) (issize crate1 large)
    (lies crate2 c1-3) (iscolour crate2 blue) (issize crate2 large)
    (lies jar1 c1-6) (iscolour jar1 white) (issize jar1 small)
    (reaches c3-6 shelf1)
    (reaches c3-1 shelf2)
    (reaches c5-6 shelf3)
    (step-up c1-2 c1-1) (step-up c4-2 c4-1) (step-up c7-2 c7-1) (step-up c1-3 c1-2) (step-up c4-3 c4-2) (step-up c7-3 c7-2)
    (step-up c1-4 c1-3) (step-up c4-4 c4-3) (step-up c7-4 c7-3) (step-up c4-5 c4-4) (step-up c4-6 c4-5)
    (step-down c1-1 c1-2) (step-down c4-1 c4-2) (step-down c7-1 c7-2) (step-down c1-2 c1-3) (step-down c4-2 c4-3) (step-down c7-2 c7-3)
    (step-down c1-3 c1-4) (step-down c4-3 c4-4) (step-down c7-3 c7-4) (step-down c4-4 c4-5) (step-down c4-5 c4-6)
    (step-left c2-1 c1-1) (step-left c3-1 c2-1) (step-left c4-1 c3-1) (step-left c5-1 c4-1) (step-left c6-1 c5-1) (step-left c7-1 c6-1)
    (step-left c2-4 c1-4) (step-left c3-4 c2-4) (step-left c4-4 c3-4) (step-left c5-4 c4-4) (step-left c6-4 c5-4) (step-left c7-4 c6-4)
    (step-left c2-6 c1-6) (step-left c3-6 c2-6) (step-left c4-6 c3-6) (step-left c5-6 c4-6) (step-left c6-6 c5-6) (step-left c7-6 c6-6)
    (step-right c1-1 c2-1) (step-right c2-1 c3-1) (step-right c3-1 c4-1) (step-right c4-1 c5-1) (step-right c5-1 c6-1) (step-right c6-1 c7-1)
    (step-right c1-4 c2-4) (step-right c2-4 c3-4) (step-right c3-4 c4-4) (step-right c4-4 c5-4) (step-right c5-4 c6-4) (step-right c6-4 c7-4)
    (step-right c1-6 c2-6) (step-right c2-6 c3-6) (step-right c3-6 c4-6) (step-right c4-6 c5-6) (step-right c5-6 c6-6) (step-right c6-6 c7-6)
  )
  (:goal (and (holding human crate2) (holding human jar1)))
)
