; An open floor with pillars; shelves 1 and 2 on the top wall, shelf 3 on the left wall.
; Map (x grows to the right, y downwards; cell cX-Y; # wall, digits: shelves,
;      letters: items, H / R: where the human / robot start):
;   ##1###2##
;   #a..#..b#
;   #.#.#.#.#
;   #c..R..d#
;   #.#.#.#.#
;   3...H...#
;   #.#.#.#.#
;   #e.....f#
;   #########
;   items: a=can1 (small red can), b=can2 (small yellow can), c=box1 (large blue box), d=box2 (small blue box), e=bottle1 (large green bottle), f=can3 (small yellow can)
(define (problem warehouse-8)
  (:domain warehouse)
  (:objects
    human - human
    robot - robot
    c1-1 c2-1 c3-1 c5-1 c6-1 c7-1 c1-2 c3-2 c5-2 c7-2
    c1-3 c2-3 c3-3 c4-3 c5-3 c6-3 c7-3 c1-4 c3-4 c5-4
    c7-4 c1-5 c2-5 c3-5 c4-5 c5-5 c6-5 c7-5 c1-6 c3-6
    c5-6 c7-6 c1-7 c2-7 c3-7 c4-7 c5-7 c6-7 c7-7 - cell
    shelf1 shelf2 shelf3 - shelf
    bottle1 - bottle
    box1 box2 - box
    can1 can2 can3 - can
    blue green red yellow - colour
    large small - size
  )
  (:init
    (at human c4-5) (at robot c4-3)
    (lies bottle1 c1-7) (iscolour bottle1 green) (issize bottle1 large)
    (lies box1 c1-3) (iscolour box1 blue) (issize box1 large)
    (lies box2 c7-3) (iscolour box2 blue) (issize box2 small)
    (lies can1 c1-1) (iscolour can1 red) (issize can1 small)
    (lies can2 c7-1) (iscolour can2 yellow) (issize can2 small)
    (lies can3 c7-7) (iscolour can3 yellow) (issize can3 small)
    (reaches c2-1 shelf1)
    (reaches c6-1 shelf2)
    (reaches c1-5 shelf3)
    (step-up c1-2 c1-1) (step-up c3-2 c3-1) (step-up c5-2 c5-1) (step-up c7-2 c7-1) (step-up c1-3 c1-2) (step-up c3-3 c3-2)
    (step-up c5-3 c5-2) (step-up c7-3 c7-2) (step-up c1-4 c1-3) (step-up c3-4 c3-3) (step-up c5-4 c5-3) (step-up c7-4 c7-3)
    (step-up c1-5 c1-4) (step-up c3-5 c3-4) (step-up c5-5 c5-4) (step-up c7-5 c7-4) (step-up c1-6 c1-5) (step-up c3-6 c3-5)
    (step-up c5-6 c5-5) (step-up c7-6 c7-5) (step-up c1-7 c1-6) (step-up c3-7 c3-6) (step-up c5-7 c5-6) (step-up c7-7 c7-6)
    (step-down c1-1 c1-2) (step-down c3-1 c3-2) (step-down c5-1 c5-2) (step-down c7-1 c7-2) (step-down c1-2 c1-3) (step-down c3-2 c3-3)
    (step-down c5-2 c5-3) (step-down c7-2 c7-3) (step-down c1-3 c1-4) (step-down c3-3 c3-4) (step-down c5-3 c5-4) (step-down c7-3 c7-4)
    (step-down c1-4 c1-5) (step-down c3-4 c3-5) (step-down c5-4 c5-5) (step-down c7-4 c7-5) (step-down c1-5 c1-6) (step-down c3-5 c3-6)
    (step-down c5-5 c5-6) (step-down c7-5 c7-6) (step-down c1-6 c1-7) (step-down c3-6 c3-7) (step-down c5-6 c5-7) (step-down c7-6 c7-7)
    (step-left c2-1 c1-1) (step-left c3-1 c2-1) (step-left c6-1 c5-1) (step-left c7-1 c6-1) (step-left c2-3 c1-3) (step-left c3-3 c2-3)
    (step-left c4-3 c3-3) (step-left c5-3 c4-3) (step-left c6-3 c5-3) (step-left c7-3 c6-3) (step-left c2-5 c1-5) (step-left c3-5 c2-5)
    (step-left c4-5 c3-5) (step-left c5-5 c4-5) (step-left c6-5 c5-5) (step-left c7-5 c6-5) (step-left c2-7 c1-7) (step-left c3-7 c2-7)
    (step-left c4-7 c3-7) (step-left c5-7 c4-7) (step-left c6-7 c5-7) (step-left c7-7 c6-7)
    (step-right c1-1 c2-1) (step-right c2-1 c3-1) (step-right c5-1 c6-1) (step-right c6-1 c7-1) (step-right c1-3 c2-3) (step-right c2-3 c3-3)
    (step-right c3-3 c4-3) (step-right c4-3 c5-3) (step-right c5-3 c6-3) (step-right c6-3 c7-3) (step-right c1-5 c2-5) (step-right c2-5 c3-5)
    (step-right c3-5 c4-5) (step-right c4-5 c5-5) (step-right c5-5 c6-5) (step-right c6-5 c7-5) (step-right c1-7 c2-7) (step-right c2-7 c3-7)
    (step-right c3-7 c4-7) (step-right c4-7 c5-7) (step-right c5-7 c6-7) (step-right c6-7 c7-7)
  )
  (:goal (and (on can2 shelf2) (on can3 shelf2)))
)
