; Ground floor: lobby (lift), corridor, pharmacy (locked; the white keycard lying in the lobby opens it), laundry (door closed). First floor: landing (lift), day room (trolley 1), south ward (beds 1-3), office (door closed; cabinet 1).
(define (problem hospital-5)
  (:domain hospital)
  (:objects
    human - human
    robot - robot
    lobby corridor pharmacy laundry landing day-room south-ward office - area
    bed1 bed2 bed3 - bed
    trolley1 - trolley
    cabinet1 - cabinet
    keycard1 - keycard
    syrup1 syrup2 - syrup
    towel1 towel2 - towel
    bandage1 - bandage
    red green white orange - colour
    small large - size
  )
  (:init
    (at human south-ward) (at robot corridor)
    (liftstop lobby) (liftstop landing)
    (link lobby corridor) (link corridor lobby)
    (link corridor pharmacy) (link pharmacy corridor) (closed corridor pharmacy) (closed pharmacy corridor) (locked corridor pharmacy) (locked pharmacy corridor)
    (link lobby laundry) (link laundry lobby) (closed lobby laundry) (closed laundry lobby)
    (link landing day-room) (link day-room landing)
    (link landing south-ward) (link south-ward landing)
    (link landing office) (link office landing) (closed landing office) (closed office landing)
    (located bed1 south-ward) (located bed2 south-ward) (located bed3 south-ward) (located trolley1 day-room) (located cabinet1 office)
    (in keycard1 lobby) (iscolour keycard1 white) (issize keycard1 small) (opens keycard1 pharmacy)
    (in syrup1 pharmacy) (iscolour syrup1 green) (issize syrup1 small)
    (in syrup2 pharmacy) (iscolour syrup2 red) (issize syrup2 small)
    (in towel1 laundry) (iscolour towel1 white) (issize towel1 large)
    (in towel2 laundry) (iscolour towel2 orange) (issize towel2 large)
    (in bandage1 office) (iscolour bandage1 red) (issize bandage1 small)
  )
  (:goal (and (on towel1 bed2) (on towel2 bed2)))
)
