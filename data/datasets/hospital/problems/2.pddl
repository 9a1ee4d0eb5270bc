; Ground floor: reception (lift), west ward (beds 1-3), laundry (door closed). First floor: landing (lift), corridor, storeroom (door closed), treatment room (cabinets 1-2). No locked doors.
(define (problem hospital-2)
  (:domain hospital)
  (:objects
    human - human
    robot - robot
    reception west-ward laundry landing corridor storeroom treatment-room - area
    bed1 bed2 bed3 - bed
    cabinet1 cabinet2 - cabinet
    towel1 towel2 - towel
    blanket1 - blanket
    bandage1 bandage2 - bandage
    splint1 - splint
    blue white pink - colour
    small large - size
  )
  (:init
    (at human west-ward) (at robot landing)
    (liftstop reception) (liftstop landing)
    (link reception west-ward) (link west-ward reception)
    (link reception laundry) (link laundry reception) (closed reception laundry) (closed laundry reception)
    (link landing corridor) (link corridor landing)
    (link corridor storeroom) (link storeroom corridor) (closed corridor storeroom) (closed storeroom corridor)
    (link corridor treatment-room) (link treatment-room corridor)
    (located bed1 west-ward) (located bed2 west-ward) (located bed3 west-ward) (located cabinet1 treatment-room) (located cabinet2 treatment-room)
    (in towel1 laundry) (iscolour towel1 white) (issize towel1 small)
    (in blanket1 laundry) (iscolour blanket1 white) (issize blanket1 large)
    (in towel2 storeroom) (iscolour towel2 pink) (issize towel2 small)
    (in bandage1 storeroom) (iscolour bandage1 pink) (issize bandage1 small)
    (in bandage2 storeroom) (iscolour bandage2 white) (issize bandage2 large)
    (in splint1 treatment-room) (iscolour splint1 blue) (issize splint1 large)
  )
  (:goal (and (on towel1 bed1) (on towel2 bed1)))
)
