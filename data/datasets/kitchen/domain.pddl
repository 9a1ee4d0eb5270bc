; Kitchen recipes: a human cook makes one dish and a helper robot fetches.
; Agents take turns (human, robot, human, ...); every action hands the turn
; to the next agent. Only the human cooks. A dish is cooked at the counter
; from its two or three ingredients lying on the counter, with its one piece
; of kitchenware (a pan, a bowl, a whisk, ...) in the cook's hand, as listed
; by the problem's (recipe2 ...) / (recipe3 ...) facts. Items lie in places:
; the fridge, the cupboard and the drawer are containers that may start
; closed and must then be opened before anything is taken out of them.
; Held items are put down only on the counter (the only place a put-down
; item is of any use) and never taken back from it, and containers are
; never closed again: all three keep the search small.
(define (domain kitchen-recipes)
  (:requirements :typing :negative-preconditions :equality :conditional-effects)
  (:types
    human robot - agent
    ingredient kitchenware - item
    fruit vegetable dairy staple egg - ingredient
    apple banana lemon - fruit
    tomato pepper onion potato - vegetable
    milk cheese butter cream - dairy
    flour sugar oats rice - staple
    cookware utensil - kitchenware
    pan pot bowl tray - cookware
    whisk knife spoon grater - utensil
    fridge cupboard drawer - container
    container pantry - storage
    storage counter - place
    agent item place dish size colour material - object)
  (:predicates
    (at ?a - agent ?p - place)
    (in ?i - item ?p - place)
    (holding ?a - agent ?i - item)
    (closed ?p - place)
    (issize ?o - object ?s - size)
    (iscolour ?o - object ?c - colour)
    (ismaterial ?o - object ?m - material)
    (recipe2 ?d - dish ?x - ingredient ?y - ingredient ?k - kitchenware)
    (recipe3 ?d - dish ?x - ingredient ?y - ingredient ?z - ingredient ?k - kitchenware)
    (made ?d - dish)
    (active ?a - agent)
    (next-turn ?a - agent ?b - agent)
    (frozen ?a - agent))

  (:action move
   :parameters (?a - agent ?from - place ?to - place)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?from) (not (= ?from ?to)))
   :effect (and (not (at ?a ?from)) (at ?a ?to)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action open
   :parameters (?a - agent ?c - container)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?c) (closed ?c))
   :effect (and (not (closed ?c))
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action pickup
   :parameters (?a - agent ?i - item ?p - storage)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?p) (in ?i ?p) (not (closed ?p)))
   :effect (and (not (in ?i ?p)) (holding ?a ?i)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action putdown
   :parameters (?a - agent ?i - item ?p - counter)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?p) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (in ?i ?p)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action handover
   :parameters (?a - agent ?b - agent ?i - item ?p - place)
   :precondition (and (active ?a) (not (frozen ?a)) (not (= ?a ?b))
                      (at ?a ?p) (at ?b ?p) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (holding ?b ?i)
                (not (active ?a))
                (forall (?c - agent) (when (next-turn ?a ?c) (active ?c)))))

  (:action cook2
   :parameters (?a - human ?d - dish ?x - ingredient ?y - ingredient ?k - kitchenware ?p - counter)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?p)
                      (recipe2 ?d ?x ?y ?k) (holding ?a ?k) (in ?x ?p) (in ?y ?p)
                      (not (made ?d)))
   :effect (and (made ?d) (not (in ?x ?p)) (not (in ?y ?p))
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action cook3
   :parameters (?a - human ?d - dish ?x - ingredient ?y - ingredient ?z - ingredient ?k - kitchenware ?p - counter)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?p)
                      (recipe3 ?d ?x ?y ?z ?k) (holding ?a ?k) (in ?x ?p) (in ?y ?p) (in ?z ?p)
                      (not (made ?d)))
   :effect (and (made ?d) (not (in ?x ?p)) (not (in ?y ?p)) (not (in ?z ?p))
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action wait
   :parameters (?a - agent)
   :precondition (active ?a)
   :effect (and (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))
)
