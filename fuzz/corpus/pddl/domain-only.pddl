; A typed blocks world with action costs and a conditional effect, used to
; check that the engine is not tied to the two dataset domains.
(define (domain blocks-typed)
  (:requirements :typing :adl :action-costs :numeric-fluents)
  (:types block - object table - object)
  (:constants table - table)
  (:predicates (on ?x - block ?y - object) (clear ?x - object) (holding ?x - block)
               (handempty) (heavy ?x - block))
  (:functions (total-cost) - number (moves) - integer)
  (:action pick
    :parameters (?x - block ?y - object)
    :precondition (and (handempty) (clear ?x) (on ?x ?y) (not (= ?x ?y)))
    :effect (and (holding ?x) (not (handempty)) (not (on ?x ?y)) (not (clear ?x))
                 (when (not (= ?y table)) (clear ?y))
                 (increase (moves) 1)
                 (increase (total-cost) 2)))
  (:action place
    :parameters (?x - block ?y - object)
    :precondition (and (holding ?x) (or (= ?y table) (clear ?y)) (not (= ?x ?y))
                       (imply (heavy ?x) (= ?y table)))
    :effect (and (on ?x ?y) (handempty) (not (holding ?x)) (clear ?x)
                 (when (not (= ?y table)) (not (clear ?y)))
                 (increase (total-cost) 1)))
)
