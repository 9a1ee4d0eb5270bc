; Warehouse: a human restocks shelves on a grid map and a robot helps.
; The floor is a grid of cells; two cells are joined when an agent can step
; from one to the other (static step-up/down/left/right facts), so walls are
; simply cells that are missing or not joined. Items (cans, boxes, crates,
; bottles, jars, bags) lie on floor cells. Shelves are fixtures that stand
; where a wall would be: nobody walks into a shelf; an agent reaches it from
; the floor cells next to it ((reaches ?c ?s)). An item put on a shelf stays
; there. Agents may share a cell, carry several items and hand items over
; when they stand on the same cell.
; Turns are not written here: the pack says "turns": "alternate" and clips
; adds them, the no-op (wait) and frozen.
(define (domain warehouse)
  (:requirements :typing :negative-preconditions :equality)
  (:types
    human robot - agent
    can box crate bottle jar bag - item
    agent item cell shelf colour size - object)
  (:predicates
    (at ?a - agent ?c - cell)
    (lies ?i - item ?c - cell)
    (holding ?a - agent ?i - item)
    (on ?i - item ?s - shelf)
    (step-up ?from - cell ?to - cell)
    (step-down ?from - cell ?to - cell)
    (step-left ?from - cell ?to - cell)
    (step-right ?from - cell ?to - cell)
    (reaches ?c - cell ?s - shelf)
    (iscolour ?i - item ?c - colour)
    (issize ?i - item ?z - size))

  (:action up
   :parameters (?a - agent ?from - cell ?to - cell)
   :precondition (and (at ?a ?from) (step-up ?from ?to))
   :effect (and (not (at ?a ?from)) (at ?a ?to)))

  (:action down
   :parameters (?a - agent ?from - cell ?to - cell)
   :precondition (and (at ?a ?from) (step-down ?from ?to))
   :effect (and (not (at ?a ?from)) (at ?a ?to)))

  (:action left
   :parameters (?a - agent ?from - cell ?to - cell)
   :precondition (and (at ?a ?from) (step-left ?from ?to))
   :effect (and (not (at ?a ?from)) (at ?a ?to)))

  (:action right
   :parameters (?a - agent ?from - cell ?to - cell)
   :precondition (and (at ?a ?from) (step-right ?from ?to))
   :effect (and (not (at ?a ?from)) (at ?a ?to)))

  ; pick up an item lying on the agent's cell
  (:action pickup
   :parameters (?a - agent ?i - item ?c - cell)
   :precondition (and (at ?a ?c) (lies ?i ?c))
   :effect (and (not (lies ?i ?c)) (holding ?a ?i)))

  ; put a held item on a shelf within reach of the agent's cell
  (:action put
   :parameters (?a - agent ?i - item ?s - shelf ?c - cell)
   :precondition (and (at ?a ?c) (reaches ?c ?s) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (on ?i ?s)))

  ; give a held item to the other agent on the same cell
  (:action handover
   :parameters (?a - agent ?b - agent ?i - item ?c - cell)
   :precondition (and (not (= ?a ?b)) (at ?a ?c) (at ?b ?c) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (holding ?b ?i)))
)
