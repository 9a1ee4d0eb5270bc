; Three floors. Ground: lobby (lift), pharmacy (locked; the blue keycard in the storeroom opens it), storeroom (door closed). First: landing (lift), north ward (beds 1-3). Second: upper landing (lift), lab (cabinets 1-2), office.
(define (problem hospital-6)
  (:domain hospital)
  (:objects
    human - human
    robot - robot
    lobby pharmacy storeroom landing north-ward upper-landing lab office - area
    bed1 bed2 bed3 - bed
    cabinet1 cabinet2 - cabinet
    keycard1 - keycard
    inhaler1 inhaler2 - inhaler
    thermometer1 thermometer2 - thermometer
    splint1 - splint
    blue white grey - colour
    small large - size
  )
  (:init
    (at human north-ward) (at robot lobby)
    (liftstop lobby) (liftstop landing) (liftstop upper-landing)
    (link lobby pharmacy) (link pharmacy lobby) (closed lobby pharmacy) (closed pharmacy lobby) (locked lobby pharmacy) (locked pharmacy lobby)
    (link lobby storeroom) (link storeroom lobby) (closed lobby storeroom) (closed storeroom lobby)
    (link landing north-ward) (link north-ward landing)
    (link upper-landing lab) (link lab upper-landing)
    (link upper-landing office) (link office upper-landing)
    (located bed1 north-ward) (located bed2 north-ward) (located bed3 north-ward) (located cabinet1 lab) (located cabinet2 lab)
    (in keycard1 storeroom) (iscolour keycard1 blue) (issize keycard1 small) (opens keycard1 pharmacy)
    (in inhaler1 pharmacy) (iscolour inhaler1 blue) (issize inhaler1 small)
    (in inhaler2 pharmacy) (iscolour inhaler2 white) (issize inhaler2 small)
    (in thermometer1 storeroom) (iscolour thermometer1 grey) (issize thermometer1 small)
    (in thermometer2 office) (iscolour thermometer2 white) (issize thermometer2 large)
    (in splint1 storeroom) (iscolour splint1 white) (issize splint1 large)
  )
  (:goal (holding human inhaler1))
)
