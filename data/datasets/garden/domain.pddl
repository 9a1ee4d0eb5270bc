; Garden: a gardener (the human) wants to do one garden job; a robot helps
; by fetching and carrying things, putting them down where the job is done,
; and unlocking the shed or greenhouse. Agents take turns (human, robot,
; human, ...); every action hands the turn to the next agent.
; A job is done by the gardener alone, at the job's place, with two items
; lying there and the job's tool in the gardener's hand, as listed by the
; problem's (job-needs ...) facts. The shed and the greenhouse may be locked:
; nobody can go in until someone holding the matching key unlocks the door
; from the place it opens onto. Items are put down only at work places
; (beds, patio, gate, ...), and an item once put down stays there: nothing
; else would help, and it keeps the search small.
(define (domain garden)
  (:requirements :typing :negative-preconditions :equality :conditional-effects)
  (:types
    human robot - agent
    tool plant container supply key - item
    trowel shears hose spade rake - tool
    rose fern tulip herb seedling - plant
    pot tray basket - container
    compost fertilizer seeds mulch twine - supply
    item agent place job colour size material - object)
  (:predicates
    (at ?a - agent ?p - place)
    (in ?i - item ?p - place)
    (holding ?a - agent ?i - item)
    (placed ?i - item)
    (worksite ?p - place)
    (locked ?p - place)
    (door ?p - place ?q - place)
    (opens ?k - key ?p - place)
    (iscolour ?i - item ?c - colour)
    (issize ?i - item ?z - size)
    (ismaterial ?i - item ?m - material)
    (job-needs ?j - job ?x - item ?y - item ?t - tool ?p - place)
    (done ?j - job)
    (active ?a - agent)
    (next-turn ?a - agent ?b - agent)
    (frozen ?a - agent))

  ; walk to any place that is not locked
  (:action move
   :parameters (?a - agent ?from - place ?to - place)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?from) (not (= ?from ?to))
                      (not (locked ?to)))
   :effect (and (not (at ?a ?from)) (at ?a ?to)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  ; pick up an item lying at the agent's place (not one put down for a job)
  (:action pickup
   :parameters (?a - agent ?i - item ?p - place)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?p) (in ?i ?p) (not (placed ?i)))
   :effect (and (not (in ?i ?p)) (holding ?a ?i)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  ; put a held item down at a work place
  (:action put
   :parameters (?a - agent ?i - item ?p - place)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?p) (worksite ?p) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (in ?i ?p) (placed ?i)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  ; give a held item to the other agent at the same place
  (:action handover
   :parameters (?a - agent ?b - agent ?i - item ?p - place)
   :precondition (and (active ?a) (not (frozen ?a)) (not (= ?a ?b))
                      (at ?a ?p) (at ?b ?p) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (holding ?b ?i)
                (not (active ?a))
                (forall (?c - agent) (when (next-turn ?a ?c) (active ?c)))))

  ; unlock a locked place with its key, standing where its door opens onto
  (:action unlock
   :parameters (?a - agent ?k - key ?p - place ?q - place)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?q) (door ?p ?q)
                      (locked ?p) (opens ?k ?p) (holding ?a ?k))
   :effect (and (not (locked ?p))
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  ; only the gardener does a job: both items lie at the job's place and the
  ; gardener holds the tool; the items are used up, the tool stays in hand
  (:action work
   :parameters (?a - human ?j - job ?x - item ?y - item ?t - tool ?p - place)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?p)
                      (job-needs ?j ?x ?y ?t ?p) (in ?x ?p) (in ?y ?p) (holding ?a ?t)
                      (not (done ?j)))
   :effect (and (done ?j) (not (in ?x ?p)) (not (in ?y ?p))
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action wait
   :parameters (?a - agent)
   :precondition (active ?a)
   :effect (and (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))
)
