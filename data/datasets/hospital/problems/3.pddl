; Ground floor: lobby (lift), corridor, pharmacy (locked; the red keycard in the office opens it), office (door closed). First floor: landing (lift), north ward (beds 1-2), south ward (beds 3-4).
(define (problem hospital-3)
  (:domain hospital)
  (:objects
    human - human
    robot - robot
    lobby corridor pharmacy office landing north-ward south-ward - area
    bed1 bed2 bed3 bed4 - bed
    keycard1 - keycard
    thermometer1 thermometer2 - thermometer
    inhaler1 inhaler2 - inhaler
    syrup1 - syrup
    red blue white grey orange - colour
    small large - size
  )
  (:init
    (at human north-ward) (at robot lobby)
    (liftstop lobby) (liftstop landing)
    (link lobby corridor) (link corridor lobby)
    (link corridor pharmacy) (link pharmacy corridor) (closed corridor pharmacy) (closed pharmacy corridor) (locked corridor pharmacy) (locked pharmacy corridor)
    (link lobby office) (link office lobby) (closed lobby office) (closed office lobby)
    (link landing north-ward) (link north-ward landing)
    (link landing south-ward) (link south-ward landing)
    (located bed1 north-ward) (located bed2 north-ward) (located bed3 south-ward) (located bed4 south-ward)
    (in keycard1 office) (iscolour keycard1 red) (issize keycard1 small) (opens keycard1 pharmacy)
    (in thermometer1 office) (iscolour thermometer1 white) (issize thermometer1 small)
    (in thermometer2 office) (iscolour thermometer2 grey) (issize thermometer2 small)
    (in inhaler1 pharmacy) (iscolour inhaler1 blue) (issize inhaler1 small)
    (in inhaler2 pharmacy) (iscolour inhaler2 orange) (issize inhaler2 small)
    (in syrup1 pharmacy) (iscolour syrup1 red) (issize syrup1 large)
  )
  (:goal (on inhaler1 bed2))
)
