; Storeroom: the workshop of data/datasets/workshop grown for profiling.
; A human builds things at a workbench and a robot helps by fetching. Some
; parts and tools are kept in containers that must be opened first, and some
; containers are locked and open only with their key (an item like any
; other: it is picked up, carried and handed over, and stays in hand when it
; unlocks). Agents take turns with the idiom of the workshop and both paper
; domains: every action deactivates its agent and activates the next one
; through the static (next-turn ?a ?b), so grounding makes it a plain effect.
(define (domain storeroom)
  (:requirements :typing :negative-preconditions :equality :conditional-effects)
  (:types
    human robot - agent
    tool part key - item
    hammer saw screwdriver wrench drill - tool
    plank panel leg rod bracket dowel - part
    item agent station container product size material - object)
  (:predicates
    (at ?a - agent ?s - station)
    (on ?i - item ?s - station)
    (in ?i - item ?c - container)
    (stands ?c - container ?s - station)
    (open ?c - container)
    (locked ?c - container)
    (fits ?k - key ?c - container)
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

  (:action unlock
   :parameters (?a - agent ?k - key ?c - container ?s - station)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?s) (stands ?c ?s) (locked ?c)
                      (fits ?k ?c) (holding ?a ?k))
   :effect (and (not (locked ?c))
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action open
   :parameters (?a - agent ?c - container ?s - station)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?s) (stands ?c ?s) (not (locked ?c)) (not (open ?c)))
   :effect (and (open ?c)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action take
   :parameters (?a - agent ?i - item ?c - container ?s - station)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?s) (stands ?c ?s) (open ?c) (in ?i ?c))
   :effect (and (not (in ?i ?c)) (holding ?a ?i)
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
