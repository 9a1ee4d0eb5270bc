; A ring of aisles round a small alcove; shelves 1 and 2 on the top wall, shelf 3 at the end of a short dead end.
; Map (x grows to the right, y downwards; cell cX-Y; # wall, digits: shelves,
;      letters: items, H / R: where the human / robot start):
;   ###1#2###
;   #a.....b#
;   #.#####.#
;   #.#d.e#.#
;   #.#.#.#.#
;   #...H...#
;   #.##.##.#
;   #fg#R#.h#
;   ####3####
;   items: a=box1 (large green box), b=box2 (small green box), d=jar1 (large white jar), e=jar2 (small white jar), f=can2 (small blue can), g=can1 (small red can), h=jar3 (small yellow jar)
(define (problem warehouse-6)
  (:domain warehouse)
  (:objects
    human - human
    robot - robot
    c1-1 c2-1 c3-1 c4-1 c5-1 c6-1 c7-1 c1-2 c7-2 c1-3
    c3-3 c4-3 c5-3 c7-3 c1-4 c3-4 c5-4 c7-4 c1-5 c2-5
    c3-5 c4-5 c5-5 c6-5 c7-5 c1-6 c4-6 c7-6 c1-7 c2-7
    c4-7 c6-7 c7-7 - cell
    shelf1 shelf2 shelf3 - shelf
    box1 box2 - box
    can1 can2 - can
    jar1 jar2 jar3 - jar
    blue green red white yellow - colour
    large small - size
  )
  (:init
    (at human c4-5) (at robot c4-7)
    (lies box1 c1-1) (iscolour box1 green) (issize box1 large)
    (lies box2 c7-1) (iscolour box2 green) (issize box2 small)
    (lies can1 c2-7) (iscolour can1 red) (issize can1 small)
    (lies can2 c1-7) (iscolour can2 blue) (issize can2 small)
    (lies jar1 c3-3) (iscolour jar1 white) (issize jar1 large)
    (lies jar2 c5-3) (iscolour jar2 white) (issize jar2 small)
    (lies jar3 c7-7) (iscolour jar3 yellow) (issize jar3 small)
    (reaches c3-1 shelf1)
    (reaches c5-1 shelf2)
    (reaches c4-7 shelf3)
    (step-up c1-2 c1-1) (step-up c7-2 c7-1) (step-up c1-3 c1-2) (step-up c7-3 c7-2) (step-up c1-4 c1-3) (step-up c3-4 c3-3)
    (step-up c5-4 c5-3) (step-up c7-4 c7-3) (step-up c1-5 c1-4) (step-up c3-5 c3-4) (step-up c5-5 c5-4) (step-up c7-5 c7-4)
    (step-up c1-6 c1-5) (step-up c4-6 c4-5) (step-up c7-6 c7-5) (step-up c1-7 c1-6) (step-up c4-7 c4-6) (step-up c7-7 c7-6)
    (step-down c1-1 c1-2) (step-down c7-1 c7-2) (step-down c1-2 c1-3) (step-down c7-2 c7-3) (step-down c1-3 c1-4) (step-down c3-3 c3-4)
    (step-down c5-3 c5-4) (step-down c7-3 c7-4) (step-down c1-4 c1-5) (step-down c3-4 c3-5) (step-down c5-4 c5-5) (step-down c7-4 c7-5)
    (step-down c1-5 c1-6) (step-down c4-5 c4-6) (step-down c7-5 c7-6) (step-down c1-6 c1-7) (step-down c4-6 c4-7) (step-down c7-6 c7-7)
    (step-left c2-1 c1-1) (step-left c3-1 c2-1) (step-left c4-1 c3-1) (step-left c5-1 c4-1) (step-left c6-1 c5-1) (step-left c7-1 c6-1)
    (step-left c4-3 c3-3) (step-left c5-3 c4-3) (step-left c2-5 c1-5) (step-left c3-5 c2-5) (step-left c4-5 c3-5) (step-left c5-5 c4-5)
    (step-left c6-5 c5-5) (step-left c7-5 c6-5) (step-left c2-7 c1-7) (step-left c7-7 c6-7)
    (step-right c1-1 c2-1) (step-right c2-1 c3-1) (step-right c3-1 c4-1) (step-right c4-1 c5-1) (step-right c5-1 c6-1) (step-right c6-1 c7-1)
    (step-right c3-3 c4-3) (step-right c4-3 c5-3) (step-right c1-5 c2-5) (step-right c2-5 c3-5) (step-right c3-5 c4-5) (step-right c4-5 c5-5)
    (step-right c5-5 c6-5) (step-right c6-5 c7-5) (step-right c1-7 c2-7) (step-right c6-7 c7-7)
  )
  (:goal (and (on jar1 shelf1) (on jar2 shelf1)))
)
