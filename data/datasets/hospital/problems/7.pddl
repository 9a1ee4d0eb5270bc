; Ground floor: reception (lift), corridor, pharmacy (locked; the red keycard in the office opens it), office. First floor: landing (lift), treatment room (cabinets 1-3), west ward (beds 1-2), laundry (door closed).
(define (problem hospital-7)
  (:domain hospital)
  (:objects
    human - human
    robot - robot
    reception corridor pharmacy office landing treatment-room west-ward laundry - area
    cabinet1 cabinet2 cabinet3 - cabinet
    bed1 bed2 - bed
    keycard1 - keycard
    pills1 pills2 pills3 - pills
    bandage1 - bandage
    blanket1 - blanket
    red green white - colour
    small large - size
  )
  (:init
    (at human treatment-room) (at robot landing)
    (liftstop reception) (liftstop landing)
    (link reception corridor) (link corridor reception)
    (link corridor pharmacy) (link pharmacy corridor) (closed corridor pharmacy) (closed pharmacy corridor) (locked corridor pharmacy) (locked pharmacy corridor)
    (link corridor office) (link office corridor)
    (link landing treatment-room) (link treatment-room landing)
    (link landing west-ward) (link west-ward landing)
    (link landing laundry) (link laundry landing) (closed landing laundry) (closed laundry landing)
    (located cabinet1 treatment-room) (located cabinet2 treatment-room) (located cabinet3 treatment-room) (located bed1 west-ward) (located bed2 west-ward)
    (in keycard1 office) (iscolour keycard1 red) (issize keycard1 small) (opens keycard1 pharmacy)
    (in pills1 pharmacy) (iscolour pills1 green) (issize pills1 small)
    (in pills2 pharmacy) (iscolour pills2 red) (issize pills2 small)
    (in pills3 pharmacy) (iscolour pills3 white) (issize pills3 small)
    (in bandage1 laundry) (iscolour bandage1 green) (issize bandage1 large)
    (in blanket1 laundry) (iscolour blanket1 red) (issize blanket1 large)
  )
  (:goal (on pills1 cabinet3))
)
