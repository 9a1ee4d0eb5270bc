; A maze of short aisles: bottles at the top, a jar on the left, crates at the bottom; the robot starts in a dead end.
; Map (x grows to the right, y downwards; cell cX-Y; # wall, digits: shelves,
;      letters: items, H / R: where the human / robot start):
;   #########
;   #a.#b..c#
;   #..#.##.#
;   #g....#.#
;   ###.#.#.#
;   1...#...2
;   #.###.#e#
;   #d..H.#R#
;   #####3###
;   items: a=bottle1 (large red bottle), b=bottle2 (small red bottle), c=bottle3 (large green bottle), g=jar1 (small white jar), e=crate2 (large blue crate), d=crate1 (large yellow crate)
(define (problem warehouse-5)
  (:domain warehouse)
  (:objects
    human - human
    robot - robot
    c1-1 c2-1 c4-1 c5-1 c6-1 c7-1 c1-2 c2-2 c4-2 c7-2
    c1-3 c2-3 c3-3 c4-3 c5-3 c7-3 c3-4 c5-4 c7-4 c1-5
    c2-5 c3-5 c5-5 c6-5 c7-5 c1-6 c5-6 c7-6 c1-7 c2-7
    c3-7 c4-7 c5-7 c7-7 - cell
    shelf1 shelf2 shelf3 - shelf
    bottle1 bottle2 bottle3 - bottle
    crate1 crate2 - crate
    jar1 - jar
    blue green red white yellow - colour
    large small - size
  )
  (:init
    (at human c4-7) (at robot c7-7)
    (lies bottle1 c1-1) (iscolour bottle1 red) (issize bottle1 large)
    (lies bottle2 c4-1) (iscolour bottle2 red) (issize bottle2 small)
    (lies bottle3 c7-1) (iscolour bottle3 green) (issize bottle3 large)
    (lies crate1 c1-7) (iscolour crate1 yellow) (issize crate1 large)
    (lies crate2 c7-6) (iscolour crate2 blue) (issize crate2 large)
    (lies jar1 c1-3) (iscolour jar1 white) (issize jar1 small)
    (reaches c1-5 shelf1)
    (reaches c7-5 shelf2)
    (reaches c5-7 shelf3)
    (step-up c1-2 c1-1) (step-up c2-2 c2-1) (step-up c4-2 c4-1) (step-up c7-2 c7-1) (step-up c1-3 c1-2) (step-up c2-3 c2-2)
    (step-up c4-3 c4-2) (step-up c7-3 c7-2) (step-up c3-4 c3-3) (step-up c5-4 c5-3) (step-up c7-4 c7-3) (step-up c3-5 c3-4)
    (step-up c5-5 c5-4) (step-up c7-5 c7-4) (step-up c1-6 c1-5) (step-up c5-6 c5-5) (step-up c7-6 c7-5) (step-up c1-7 c1-6)
    (step-up c5-7 c5-6) (step-up c7-7 c7-6)
    (step-down c1-1 c1-2) (step-down c2-1 c2-2) (step-down c4-1 c4-2) (step-down c7-1 c7-2) (step-down c1-2 c1-3) (step-down c2-2 c2-3)
    (step-down c4-2 c4-3) (step-down c7-2 c7-3) (step-down c3-3 c3-4) (step-down c5-3 c5-4) (step-down c7-3 c7-4) (step-down c3-4 c3-5)
    (step-down c5-4 c5-5) (step-down c7-4 c7-5) (step-down c1-5 c1-6) (step-down c5-5 c5-6) (step-down c7-5 c7-6) (step-down c1-6 c1-7)
    (step-down c5-6 c5-7) (step-down c7-6 c7-7)
    (step-left c2-1 c1-1) (step-left c5-1 c4-1) (step-left c6-1 c5-1) (step-left c7-1 c6-1) (step-left c2-2 c1-2) (step-left c2-3 c1-3)
    (step-left c3-3 c2-3) (step-left c4-3 c3-3) (step-left c5-3 c4-3) (step-left c2-5 c1-5) (step-left c3-5 c2-5) (step-left c6-5 c5-5)
    (step-left c7-5 c6-5) (step-left c2-7 c1-7) (step-left c3-7 c2-7) (step-left c4-7 c3-7) (step-left c5-7 c4-7)
    (step-right c1-1 c2-1) (step-right c4-1 c5-1) (step-right c5-1 c6-1) (step-right c6-1 c7-1) (step-right c1-2 c2-2) (step-right c1-3 c2-3)
    (step-right c2-3 c3-3) (step-right c3-3 c4-3) (step-right c4-3 c5-3) (step-right c1-5 c2-5) (step-right c2-5 c3-5) (step-right c5-5 c6-5)
    (step-right c6-5 c7-5) (step-right c1-7 c2-7) (step-right c2-7 c3-7) (step-right c3-7 c4-7) (step-right c4-7 c5-7)
  )
  (:goal (and (on bottle1 shelf1) (on bottle2 shelf1)))
)
