; Two rooms joined by one gap in the middle wall; the human starts in the right room, the robot in the left one.
; Map (x grows to the right, y downwards; cell cX-Y; # wall, digits: shelves,
;      letters: items, H / R: where the human / robot start):
;   ##1######
;   #a..#d.b#
;   #.c.#...#
;   #...#...#
;   2.......3
;   #...#...#
;   #e.R#.Hf#
;   ######4##
;   items: a=box1 (large red box), d=box3 (small blue box), b=can1 (small green can), c=box2 (small red box), e=bottle1 (large white bottle), f=can2 (small yellow can)
(define (problem warehouse-4)
  (:domain warehouse)
  (:objects
    human - human
    robot - robot
    c1-1 c2-1 c3-1 c5-1 c6-1 c7-1 c1-2 c2-2 c3-2 c5-2
    c6-2 c7-2 c1-3 c2-3 c3-3 c5-3 c6-3 c7-3 c1-4 c2-4
    c3-4 c4-4 c5-4 c6-4 c7-4 c1-5 c2-5 c3-5 c5-5 c6-5
    c7-5 c1-6 c2-6 c3-6 c5-6 c6-6 c7-6 - cell
    shelf1 shelf2 shelf3 shelf4 - shelf
    bottle1 - bottle
    box1 box2 box3 - box
    can1 can2 - can
    blue green red white yellow - colour
    large small - size
  )
  (:init
    (at human c6-6) (at robot c3-6)
    (lies bottle1 c1-6) (iscolour bottle1 white) (issize bottle1 large)
    (lies box1 c1-1) (iscolour box1 red) (issize box1 large)
    (lies box2 c2-2) (iscolour box2 red) (issize box2 small)
    (lies box3 c5-1) (iscolour box3 blue) (issize box3 small)
    (lies can1 c7-1) (iscolour can1 green) (issize can1 small)
    (lies can2 c7-6) (iscolour can2 yellow) (issize can2 small)
    (reaches c2-1 shelf1)
    (reaches c1-4 shelf2)
    (reaches c7-4 shelf3)
    (reaches c6-6 shelf4)
    (step-up c1-2 c1-1) (step-up c2-2 c2-1) (step-up c3-2 c3-1) (step-up c5-2 c5-1) (step-up c6-2 c6-1) (step-up c7-2 c7-1)
    (step-up c1-3 c1-2) (step-up c2-3 c2-2) (step-up c3-3 c3-2) (step-up c5-3 c5-2) (step-up c6-3 c6-2) (step-up c7-3 c7-2)
    (step-up c1-4 c1-3) (step-up c2-4 c2-3) (step-up c3-4 c3-3) (step-up c5-4 c5-3) (step-up c6-4 c6-3) (step-up c7-4 c7-3)
    (step-up c1-5 c1-4) (step-up c2-5 c2-4) (step-up c3-5 c3-4) (step-up c5-5 c5-4) (step-up c6-5 c6-4) (step-up c7-5 c7-4)
    (step-up c1-6 c1-5) (step-up c2-6 c2-5) (step-up c3-6 c3-5) (step-up c5-6 c5-5) (step-up c6-6 c6-5) (step-up c7-6 c7-5)
    (step-down c1-1 c1-2) (step-down c2-1 c2-2) (step-down c3-1 c3-2) (step-down c5-1 c5-2) (step-down c6-1 c6-2) (step-down c7-1 c7-2)
    (step-down c1-2 c1-3) (step-down c2-2 c2-3) (step-down c3-2 c3-3) (step-down c5-2 c5-3) (step-down c6-2 c6-3) (step-down c7-2 c7-3)
    (step-down c1-3 c1-4) (step-down c2-3 c2-4) (step-down c3-3 c3-4) (step-down c5-3 c5-4) (step-down c6-3 c6-4) (step-down c7-3 c7-4)
    (step-down c1-4 c1-5) (step-down c2-4 c2-5) (step-down c3-4 c3-5) (step-down c5-4 c5-5) (step-down c6-4 c6-5) (step-down c7-4 c7-5)
    (step-down c1-5 c1-6) (step-down c2-5 c2-6) (step-down c3-5 c3-6) (step-down c5-5 c5-6) (step-down c6-5 c6-6) (step-down c7-5 c7-6)
    (step-left c2-1 c1-1) (step-left c3-1 c2-1) (step-left c6-1 c5-1) (step-left c7-1 c6-1) (step-left c2-2 c1-2) (step-left c3-2 c2-2)
    (step-left c6-2 c5-2) (step-left c7-2 c6-2) (step-left c2-3 c1-3) (step-left c3-3 c2-3) (step-left c6-3 c5-3) (step-left c7-3 c6-3)
    (step-left c2-4 c1-4) (step-left c3-4 c2-4) (step-left c4-4 c3-4) (step-left c5-4 c4-4) (step-left c6-4 c5-4) (step-left c7-4 c6-4)
    (step-left c2-5 c1-5) (step-left c3-5 c2-5) (step-left c6-5 c5-5) (step-left c7-5 c6-5) (step-left c2-6 c1-6) (step-left c3-6 c2-6)
    (step-left c6-6 c5-6) (step-left c7-6 c6-6)
    (step-right c1-1 c2-1) (step-right c2-1 c3-1) (step-right c5-1 c6-1) (step-right c6-1 c7-1) (step-right c1-2 c2-2) (step-right c2-2 c3-2)
    (step-right c5-2 c6-2) (step-right c6-2 c7-2) (step-right c1-3 c2-3) (step-right c2-3 c3-3) (step-right c5-3 c6-3) (step-right c6-3 c7-3)
    (step-right c1-4 c2-4) (step-right c2-4 c3-4) (step-right c3-4 c4-4) (step-right c4-4 c5-4) (step-right c5-4 c6-4) (step-right c6-4 c7-4)
    (step-right c1-5 c2-5) (step-right c2-5 c3-5) (step-right c5-5 c6-5) (step-right c6-5 c7-5) (step-right c1-6 c2-6) (step-right c2-6 c3-6)
    (step-right c5-6 c6-6) (step-right c6-6 c7-6)
  )
  (:goal (and (on box1 shelf3) (on can1 shelf3)))
)
