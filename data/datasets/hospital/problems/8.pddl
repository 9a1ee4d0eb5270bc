; Ground floor: lobby (lift), east ward (beds 1-3), storeroom (door closed). First floor: landing (lift), corridor, pharmacy (locked; the yellow keycard in the storeroom opens it), day room (trolleys 1-2).
(define (problem hospital-8)
  (:domain hospital)
  (:objects
    human - human
    robot - robot
    lobby east-ward storeroom landing corridor pharmacy day-room - area
    bed1 bed2 bed3 - bed
    trolley1 trolley2 - trolley
    keycard1 - keycard
    blanket1 blanket2 - blanket
    towel1 towel2 - towel
    syrup1 syrup2 - syrup
    yellow pink grey - colour
    small large - size
  )
  (:init
    (at human east-ward) (at robot lobby)
    (liftstop lobby) (liftstop landing)
    (link lobby east-ward) (link east-ward lobby)
    (link lobby storeroom) (link storeroom lobby) (closed lobby storeroom) (closed storeroom lobby)
    (link landing corridor) (link corridor landing)
    (link corridor pharmacy) (link pharmacy corridor) (closed corridor pharmacy) (closed pharmacy corridor) (locked corridor pharmacy) (locked pharmacy corridor)
    (link corridor day-room) (link day-room corridor)
    (located bed1 east-ward) (located bed2 east-ward) (located bed3 east-ward) (located trolley1 day-room) (located trolley2 day-room)
    (in keycard1 storeroom) (iscolour keycard1 yellow) (issize keycard1 small) (opens keycard1 pharmacy)
    (in blanket1 storeroom) (iscolour blanket1 pink) (issize blanket1 large)
    (in towel1 storeroom) (iscolour towel1 grey) (issize towel1 small)
    (in towel2 storeroom) (iscolour towel2 pink) (issize towel2 large)
    (in blanket2 day-room) (iscolour blanket2 grey) (issize blanket2 large)
    (in syrup1 pharmacy) (iscolour syrup1 yellow) (issize syrup1 large)
    (in syrup2 pharmacy) (iscolour syrup2 pink) (issize syrup2 small)
  )
  (:goal (and (on blanket1 bed3) (on blanket2 bed3)))
)
