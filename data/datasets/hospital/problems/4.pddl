; Ground floor: reception (lift), corridor, storeroom (door closed), kitchen. First floor: landing (lift), east ward (beds 1-2), west ward (beds 3-4), treatment room (cabinets 1-2; locked, opened from the west ward by the green keycard, which lies in the kitchen).
(define (problem hospital-4)
  (:domain hospital)
  (:objects
    human - human
    robot - robot
    reception corridor storeroom kitchen landing east-ward west-ward treatment-room - area
    bed1 bed2 bed3 bed4 - bed
    cabinet1 cabinet2 - cabinet
    keycard1 - keycard
    pillow1 pillow2 pillow3 - pillow
    blanket1 - blanket
    pills1 - pills
    green white yellow - colour
    small large - size
  )
  (:init
    (at human east-ward) (at robot corridor)
    (liftstop reception) (liftstop landing)
    (link reception corridor) (link corridor reception)
    (link corridor storeroom) (link storeroom corridor) (closed corridor storeroom) (closed storeroom corridor)
    (link reception kitchen) (link kitchen reception)
    (link landing east-ward) (link east-ward landing)
    (link landing west-ward) (link west-ward landing)
    (link west-ward treatment-room) (link treatment-room west-ward) (closed west-ward treatment-room) (closed treatment-room west-ward) (locked west-ward treatment-room) (locked treatment-room west-ward)
    (located bed1 east-ward) (located bed2 east-ward) (located bed3 west-ward) (located bed4 west-ward) (located cabinet1 treatment-room) (located cabinet2 treatment-room)
    (in keycard1 kitchen) (iscolour keycard1 green) (issize keycard1 small) (opens keycard1 treatment-room)
    (in pillow1 storeroom) (iscolour pillow1 white) (issize pillow1 large)
    (in pillow2 storeroom) (iscolour pillow2 yellow) (issize pillow2 small)
    (in pillow3 storeroom) (iscolour pillow3 green) (issize pillow3 small)
    (in blanket1 storeroom) (iscolour blanket1 yellow) (issize blanket1 large)
    (in pills1 reception) (iscolour pills1 white) (issize pills1 small)
  )
  (:goal (on pillow1 bed3))
)
