; Ground floor: lobby (lift), corridor, the pharmacy (locked; the blue keycard, upstairs in the nurses' station, opens it) and the storeroom (door closed). First floor: landing (lift), east ward (beds 1-3), nurses' station (cabinets 1-2).
(define (problem hospital-1)
  (:domain hospital)
  (:objects
    human - human
    robot - robot
    lobby corridor pharmacy storeroom landing east-ward nurses-station - area
    bed1 bed2 bed3 - bed
    cabinet1 cabinet2 - cabinet
    keycard1 - keycard
    blanket1 blanket2 - blanket
    pillow1 - pillow
    pills1 pills2 - pills
    red blue white yellow - colour
    small large - size
  )
  (:init
    (at human east-ward) (at robot lobby)
    (liftstop lobby) (liftstop landing)
    (link lobby corridor) (link corridor lobby)
    (link corridor pharmacy) (link pharmacy corridor) (closed corridor pharmacy) (closed pharmacy corridor) (locked corridor pharmacy) (locked pharmacy corridor)
    (link corridor storeroom) (link storeroom corridor) (closed corridor storeroom) (closed storeroom corridor)
    (link landing east-ward) (link east-ward landing)
    (link landing nurses-station) (link nurses-station landing)
    (located bed1 east-ward) (located bed2 east-ward) (located bed3 east-ward) (located cabinet1 nurses-station) (located cabinet2 nurses-station)
    (in keycard1 nurses-station) (iscolour keycard1 blue) (issize keycard1 small) (opens keycard1 pharmacy)
    (in blanket1 storeroom) (iscolour blanket1 blue) (issize blanket1 large)
    (in blanket2 storeroom) (iscolour blanket2 white) (issize blanket2 small)
    (in pillow1 storeroom) (iscolour pillow1 red) (issize pillow1 large)
    (in pills1 pharmacy) (iscolour pills1 yellow) (issize pills1 small)
    (in pills2 pharmacy) (iscolour pills2 red) (issize pills2 small)
  )
  (:goal (on blanket1 bed2))
)
