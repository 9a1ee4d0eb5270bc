; Lab bench: a scientist (the human) runs one experiment; a robot helps.
; Agents take turns (human, robot, human, ...); every action hands the turn
; to the next agent. Reagents, samples, instruments and glassware are kept in
; storage places (cabinet, fridge, shelf, drawer); a cabinet or fridge may be
; closed and must be opened before anything is taken out of it. An experiment
; is run at one station (bench, fume hood, hotplate) from two substances
; placed at that station, with one piece of equipment in the scientist's
; hand, as listed by the problem's (protocol ...) facts. Only the scientist
; runs experiments. Items are put down only at stations and never taken back
; from them: nothing else would help, and it keeps the search small.
(define (domain lab-bench)
  (:requirements :typing :negative-preconditions :equality :conditional-effects)
  (:types
    human robot - agent
    acid base solvent indicator buffer enzyme - reagent
    culture serum - sample
    reagent sample - substance
    pipette burette thermometer - instrument
    beaker flask - glassware
    instrument glassware - equipment
    substance equipment - item
    bench hood hotplate - station
    cabinet fridge shelf drawer - storage
    station storage - place
    agent item place experiment colour size material - object)
  (:predicates
    (at ?a - agent ?p - place)
    (in ?i - item ?p - place)
    (holding ?a - agent ?i - item)
    (closed ?c - storage)
    (iscolour ?i - item ?c - colour)
    (issize ?i - item ?z - size)
    (ismaterial ?i - item ?m - material)
    (protocol ?e - experiment ?x - substance ?y - substance ?t - equipment ?s - station)
    (done ?e - experiment)
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
   :parameters (?a - agent ?c - storage)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?c) (closed ?c))
   :effect (and (not (closed ?c))
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action pickup
   :parameters (?a - agent ?i - item ?c - storage)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?c) (in ?i ?c) (not (closed ?c)))
   :effect (and (not (in ?i ?c)) (holding ?a ?i)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action put
   :parameters (?a - agent ?i - item ?s - station)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?s) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (in ?i ?s)
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action handover
   :parameters (?a - agent ?b - agent ?i - item ?p - place)
   :precondition (and (active ?a) (not (frozen ?a)) (not (= ?a ?b))
                      (at ?a ?p) (at ?b ?p) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (holding ?b ?i)
                (not (active ?a))
                (forall (?c - agent) (when (next-turn ?a ?c) (active ?c)))))

  (:action run
   :parameters (?a - human ?e - experiment ?x - substance ?y - substance ?t - equipment ?s - station)
   :precondition (and (active ?a) (not (frozen ?a)) (at ?a ?s)
                      (protocol ?e ?x ?y ?t ?s) (in ?x ?s) (in ?y ?s) (holding ?a ?t)
                      (not (done ?e)))
   :effect (and (done ?e) (not (in ?x ?s)) (not (in ?y ?s))
                (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))

  (:action wait
   :parameters (?a - agent)
   :precondition (active ?a)
   :effect (and (not (active ?a))
                (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))
)
