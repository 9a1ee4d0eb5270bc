; Three long aisles joined at their ends and by one short passage in the middle; shelves 1 and 2 stand between the upper aisles, reachable from both sides.
; Map (x grows to the right, y downwards; cell cX-Y; # wall, digits: shelves,
;      letters: items, H / R: where the human / robot start):
;   #########
;   #a.b.c..#
;   #.#####.#
;   #.......#
;   ##1#R#2##
;   #f..H...#
;   #.#####.#
;   #d.....e#
;   ####3####
;   items: a=crate1 (large red crate), b=crate2 (large green crate), c=crate3 (small red crate), f=can1 (small yellow can), d=bag1 (large white bag), e=bag2 (small white bag)
(define (problem warehouse-7)
  (:domain warehouse)
  (:objects
    human - human
    robot - robot
    c1-1 c2-1 c3-1 c4-1 c5-1 c6-1 c7-1 c1-2 c7-2 c1-3
    c2-3 c3-3 c4-3 c5-3 c6-3 c7-3 c4-4 c1-5 c2-5 c3-5
    c4-5 c5-5 c6-5 c7-5 c1-6 c7-6 c1-7 c2-7 c3-7 c4-7
    c5-7 c6-7 c7-7 - cell
    shelf1 shelf2 shelf3 - shelf
    bag1 bag2 - bag
    can1 - can
    crate1 crate2 crate3 - crate
    green red white yellow - colour
    large small - size
  )
  (:init
    (at human c4-5) (at robot c4-4)
    (lies bag1 c1-7) (iscolour bag1 white) (issize bag1 large)
    (lies bag2 c7-7) (iscolour bag2 white) (issize bag2 small)
    (lies can1 c1-5) (iscolour can1 yellow) (issize can1 small)
    (lies crate1 c1-1) (iscolour crate1 red) (issize crate1 large)
    (lies crate2 c3-1) (iscolour crate2 green) (issize crate2 large)
    (lies crate3 c5-1) (iscolour crate3 red) (issize crate3 small)
    (reaches c2-3 shelf1) (reaches c2-5 shelf1)
    (reaches c6-3 shelf2) (reaches c6-5 shelf2)
    (reaches c4-7 shelf3)
    (step-up c1-2 c1-1) (step-up c7-2 c7-1) (step-up c1-3 c1-2) (step-up c7-3 c7-2) (step-up c4-4 c4-3) (step-up c4-5 c4-4)
    (step-up c1-6 c1-5) (step-up c7-6 c7-5) (step-up c1-7 c1-6) (step-up c7-7 c7-6)
    (step-down c1-1 c1-2) (step-down c7-1 c7-2) (step-down c1-2 c1-3) (step-down c7-2 c7-3) (step-down c4-3 c4-4) (step-down c4-4 c4-5)
    (step-down c1-5 c1-6) (step-down c7-5 c7-6) (step-down c1-6 c1-7) (step-down c7-6 c7-7)
    (step-left c2-1 c1-1) (step-left c3-1 c2-1) (step-left c4-1 c3-1) (step-left c5-1 c4-1) (step-left c6-1 c5-1) (step-left c7-1 c6-1)
    (step-left c2-3 c1-3) (step-left c3-3 c2-3) (step-left c4-3 c3-3) (step-left c5-3 c4-3) (step-left c6-3 c5-3) (step-left c7-3 c6-3)
    (step-left c2-5 c1-5) (step-left c3-5 c2-5) (step-left c4-5 c3-5) (step-left c5-5 c4-5) (step-left c6-5 c5-5) (step-left c7-5 c6-5)
    (step-left c2-7 c1-7) (step-left c3-7 c2-7) (step-left c4-7 c3-7) (step-left c5-7 c4-7) (step-left c6-7 c5-7) (step-left c7-7 c6-7)
    (step-right c1-1 c2-1) (step-right c2-1 c3-1) (step-right c3-1 c4-1) (step-right c4-1 c5-1) (step-right c5-1 c6-1) (step-right c6-1 c7-1)
    (step-right c1-3 c2-3) (step-right c2-3 c3-3) (step-right c3-3 c4-3) (step-right c4-3 c5-3) (step-right c5-3 c6-3) (step-right c6-3 c7-3)
    (step-right c1-5 c2-5) (step-right c2-5 c3-5) (step-right c3-5 c4-5) (step-right c4-5 c5-5) (step-right c5-5 c6-5) (step-right c6-5 c7-5)
    (step-right c1-7 c2-7) (step-right c2-7 c3-7) (step-right c3-7 c4-7) (step-right c4-7 c5-7) (step-right c5-7 c6-7) (step-right c6-7 c7-7)
  )
  (:goal (and (on crate1 shelf1) (on crate3 shelf1)))
)
