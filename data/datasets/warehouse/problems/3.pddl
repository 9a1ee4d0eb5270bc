; Jars in the top aisles, bags on the right and in the bottom corners; most aisles are dead ends.
; Map (x grows to the right, y downwards; cell cX-Y; # wall, digits: shelves,
;      letters: items, H / R: where the human / robot start):
;   #########
;   #a..#..c#
;   #.#.#.#.#
;   #b#...#d#
;   #.##.##.#
;   1...H...2
;   ###.#.###
;   #e..#.Rf#
;   ###3#####
;   items: a=jar1 (small yellow jar), c=jar3 (small red jar), b=jar2 (large yellow jar), d=bag1 (large white bag), e=bag2 (small white bag), f=bag3 (large blue bag)
(define (problem warehouse-3)
  (:domain warehouse)
  (:objects
    human - human
    robot - robot
    c1-1 c2-1 c3-1 c5-1 c6-1 c7-1 c1-2 c3-2 c5-2 c7-2
    c1-3 c3-3 c4-3 c5-3 c7-3 c1-4 c4-4 c7-4 c1-5 c2-5
    c3-5 c4-5 c5-5 c6-5 c7-5 c3-6 c5-6 c1-7 c2-7 c3-7
    c5-7 c6-7 c7-7 - cell
    shelf1 shelf2 shelf3 - shelf
    bag1 bag2 bag3 - bag
    jar1 jar2 jar3 - jar
    blue red white yellow - colour
    large small - size
  )
  (:init
    (at human c4-5) (at robot c6-7)
    (lies bag1 c7-3) (iscolour bag1 white) (issize bag1 large)
    (lies bag2 c1-7) (iscolour bag2 white) (issize bag2 small)
    (lies bag3 c7-7) (iscolour bag3 blue) (issize bag3 large)
    (lies jar1 c1-1) (iscolour jar1 yellow) (issize jar1 small)
    (lies jar2 c1-3) (iscolour jar2 yellow) (issize jar2 large)
    (lies jar3 c7-1) (iscolour jar3 red) (issize jar3 small)
    (reaches c1-5 shelf1)
    (reaches c7-5 shelf2)
    (reaches c3-7 shelf3)
    (step-up c1-2 c1-1) (step-up c3-2 c3-1) (step-up c5-2 c5-1) (step-up c7-2 c7-1) (step-up c1-3 c1-2) (step-up c3-3 c3-2)
    (step-up c5-3 c5-2) (step-up c7-3 c7-2) (step-up c1-4 c1-3) (step-up c4-4 c4-3) (step-up c7-4 c7-3) (step-up c1-5 c1-4)
    (step-up c4-5 c4-4) (step-up c7-5 c7-4) (step-up c3-6 c3-5) (step-up c5-6 c5-5) (step-up c3-7 c3-6) (step-up c5-7 c5-6)
    (step-down c1-1 c1-2) (step-down c3-1 c3-2) (step-down c5-1 c5-2) (step-down c7-1 c7-2) (step-down c1-2 c1-3) (step-down c3-2 c3-3)
    (step-down c5-2 c5-3) (step-down c7-2 c7-3) (step-down c1-3 c1-4) (step-down c4-3 c4-4) (step-down c7-3 c7-4) (step-down c1-4 c1-5)
    (step-down c4-4 c4-5) (step-down c7-4 c7-5) (step-down c3-5 c3-6) (step-down c5-5 c5-6) (step-down c3-6 c3-7) (step-down c5-6 c5-7)
    (step-left c2-1 c1-1) (step-left c3-1 c2-1) (step-left c6-1 c5-1) (step-left c7-1 c6-1) (step-left c4-3 c3-3) (step-left c5-3 c4-3)
    (step-left c2-5 c1-5) (step-left c3-5 c2-5) (step-left c4-5 c3-5) (step-left c5-5 c4-5) (step-left c6-5 c5-5) (step-left c7-5 c6-5)
    (step-left c2-7 c1-7) (step-left c3-7 c2-7) (step-left c6-7 c5-7) (step-left c7-7 c6-7)
    (step-right c1-1 c2-1) (step-right c2-1 c3-1) (step-right c5-1 c6-1) (step-right c6-1 c7-1) (step-right c3-3 c4-3) (step-right c4-3 c5-3)
    (step-right c1-5 c2-5) (step-right c2-5 c3-5) (step-right c3-5 c4-5) (step-right c4-5 c5-5) (step-right c5-5 c6-5) (step-right c6-5 c7-5)
    (step-right c1-7 c2-7) (step-right c2-7 c3-7) (step-right c5-7 c6-7) (step-right c6-7 c7-7)
  )
  (:goal (and (on jar1 shelf1) (on jar2 shelf1)))
)
