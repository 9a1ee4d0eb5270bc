; Workshop: a human builds things at a workbench and a robot helps by
; fetching parts and tools. Agents take turns (human, robot, human, ...);
; every action hands the turn to the next agent. Only the human assembles.
; A product is made at the workbench from two parts lying on it and one
; tool in the human's hand, as listed by the problem's (recipe ...) facts.
; Items are put down only on the workbench and never taken back from it:
; nothing else would help, and it keeps the search small.
(define (domain workshop)
  (:requirements :typing :negative-preconditions :equality :conditional-effects)
  (:types
    human robot - agent
    tool part - item
    hammer saw screwdriver wrench drill - tool
    plank panel leg rod bracket dowel - part
    item agent station product size material - object)
  (:predicates
    (at ?a - agent ?s - station)
    (on ?i - item ?s - station)
    (holding ?a - agent ?i - item)
    (workbench ?s - station)
    (issize ?i - item ?z - size)
    (ismaterial ?i - item ?m - material)
    (recipe ?p - product ?x - part ?y - part ?t - tool)
    (made ?p - product)
    (active ?a - agent)
    (next-turn ?a - agent ?b - agent)
    (frozen ?a - agent))

  (:action move
   :parameters (?a - agent ?from - station ?to - station)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?from) (not (= ?from ?to)))
   :effect (and (not (at ?a ?from)) (at ?a ?to)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action pickup
   :parameters (?a - agent ?i - item ?s - station)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?s) (on ?i ?s) (not (workbench ?s)))
   :effect (and (not (on ?i ?s)) (holding ?a ?i)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action putdown
   :parameters (?a - agent ?i - item ?s - station)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?s) (workbench ?s) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (on ?i ?s)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action handover
   :parameters (?a - agent ?b - agent ?i - item ?s - station)
   :precondition (and (active ?a) (not (frozen ?a)) (not (= ?a ?b))
                      (at ?a ?s) (at ?b ?s) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (holding ?b ?i)
                (not (active ?a))
                (forall (?c - agent) (when (next-turn ?a ?c) (active ?c)))))

  (:action assemble
   :parameters (?a - human ?p - product ?x - part ?y - part ?t - tool ?s - station)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?s) (workbench ?s)
                      (recipe ?p ?x ?y ?t) (holding ?a ?t) (on ?x ?s) (on ?y ?s)
                      (not (made ?p)))
   :effect (and (made ?p) (not (on ?x ?s)) (not (on ?y ?s))
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action wait
   :parameters (?a - agent)
   :precondition (active ?a)
   :effect (and (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))
)
