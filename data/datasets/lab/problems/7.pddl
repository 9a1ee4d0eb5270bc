; A closed fridge and an open cabinet; instruments and a flask on a shelf; bench and hotplate; both agents start at the bench.
(define (problem lab-7)
  (:domain lab-bench)
  (:objects
    human - human
    robot - robot
    bench1 - bench
    hotplate1 - hotplate
    cabinet1 - cabinet
    fridge1 - fridge
    shelf1 - shelf
    solvent1 - solvent
    acid1 - acid
    buffer1 - buffer
    culture1 - culture
    enzyme1 - enzyme
    thermometer1 - thermometer
    pipette1 - pipette
    flask1 - flask
    incubation extraction hydrolysis assay - experiment
    red blue green - colour
    small large - size
    glass plastic - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human bench1)
    (at robot bench1)
    (closed fridge1)
    (in solvent1 cabinet1) (iscolour solvent1 blue) (issize solvent1 large) (ismaterial solvent1 glass)
    (in acid1 cabinet1) (iscolour acid1 green) (issize acid1 small) (ismaterial acid1 glass)
    (in buffer1 fridge1) (iscolour buffer1 red) (issize buffer1 large) (ismaterial buffer1 plastic)
    (in culture1 fridge1) (iscolour culture1 green) (issize culture1 small) (ismaterial culture1 plastic)
    (in enzyme1 fridge1) (iscolour enzyme1 blue) (issize enzyme1 small) (ismaterial enzyme1 plastic)
    (in thermometer1 shelf1) (iscolour thermometer1 red) (issize thermometer1 small) (ismaterial thermometer1 glass)
    (in pipette1 shelf1) (iscolour pipette1 blue) (issize pipette1 small) (ismaterial pipette1 plastic)
    (in flask1 shelf1) (iscolour flask1 green) (issize flask1 large) (ismaterial flask1 glass)
    (protocol incubation culture1 buffer1 thermometer1 hotplate1)
    (protocol extraction solvent1 culture1 flask1 bench1)
    (protocol hydrolysis acid1 enzyme1 thermometer1 hotplate1)
    (protocol assay buffer1 enzyme1 pipette1 bench1)
)
  (:goal (done incubation))
)
