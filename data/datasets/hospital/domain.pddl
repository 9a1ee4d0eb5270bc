; Hospital: a nurse (the human) wants a supply delivered: laid on a numbered
; bed, put into a numbered cabinet or onto a trolley, or simply into the
; nurse's own hands. A robot helps: it walks, takes the lift, opens doors,
; unlocks doors with a keycard, carries things, hands them over and puts
; them on beds and into cabinets.
;
; The building has two floors of named areas. Areas are joined by walkways
; (`link`, stated both ways); some walkways have a door that starts closed
; (`closed`, both ways) and some doors are locked as well (`locked`, both
; ways) until someone holding the keycard that opens the room unlocks it
; from next door. A lift joins the floors: `ride` goes from one lift stop
; to another. Beds, cabinets and trolleys are fixtures: they stand in an
; area (`located`), nobody stands in them, and what is put on or into them
; stays there. Agents may carry several things at once.
(define (domain hospital)
  (:requirements :typing :negative-preconditions :equality)
  (:types
    human robot - agent
    area fixture item colour size - object
    bed cabinet trolley - fixture
    linen medicine equipment keycard - item
    blanket pillow towel - linen
    pills syrup inhaler - medicine
    bandage splint thermometer - equipment)
  (:predicates
    (at ?a - agent ?r - area)
    (in ?i - item ?r - area)
    (holding ?a - agent ?i - item)
    (on ?i - item ?f - fixture)
    (located ?f - fixture ?r - area)
    (link ?r - area ?s - area)
    (closed ?r - area ?s - area)
    (locked ?r - area ?s - area)
    (opens ?k - keycard ?r - area)
    (liftstop ?r - area)
    (iscolour ?i - item ?c - colour)
    (issize ?i - item ?z - size))

  ; walk to a neighbouring area through an open walkway or doorway
  (:action move
   :parameters (?a - agent ?from - area ?to - area)
   :precondition (and (at ?a ?from) (link ?from ?to) (not (closed ?from ?to)))
   :effect (and (not (at ?a ?from)) (at ?a ?to)))

  ; take the lift from one lift stop to another (another floor)
  (:action ride
   :parameters (?a - agent ?from - area ?to - area)
   :precondition (and (at ?a ?from) (liftstop ?from) (liftstop ?to) (not (= ?from ?to)))
   :effect (and (not (at ?a ?from)) (at ?a ?to)))

  ; open the closed (not locked) door into a neighbouring area
  (:action open
   :parameters (?a - agent ?from - area ?to - area)
   :precondition (and (at ?a ?from) (link ?from ?to) (closed ?from ?to) (not (locked ?from ?to)))
   :effect (and (not (closed ?from ?to)) (not (closed ?to ?from))))

  ; swipe the keycard that opens a room, standing next door: the door is
  ; unlocked and opened
  (:action unlock
   :parameters (?a - agent ?k - keycard ?from - area ?to - area)
   :precondition (and (at ?a ?from) (link ?from ?to) (locked ?from ?to) (opens ?k ?to) (holding ?a ?k))
   :effect (and (not (locked ?from ?to)) (not (locked ?to ?from))
                (not (closed ?from ?to)) (not (closed ?to ?from))))

  ; pick up an item lying in the agent's area
  (:action pickup
   :parameters (?a - agent ?i - item ?r - area)
   :precondition (and (at ?a ?r) (in ?i ?r))
   :effect (and (not (in ?i ?r)) (holding ?a ?i)))

  ; put a held item on or into a fixture standing in the agent's area
  (:action put
   :parameters (?a - agent ?i - item ?f - fixture ?r - area)
   :precondition (and (at ?a ?r) (located ?f ?r) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (on ?i ?f)))

  ; give a held item to the other agent in the same area
  (:action handover
   :parameters (?a - agent ?b - agent ?i - item ?r - area)
   :precondition (and (not (= ?a ?b)) (at ?a ?r) (at ?b ?r) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (holding ?b ?i)))
)
