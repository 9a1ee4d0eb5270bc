; A closed fridge of reagents and a culture; one pipette in the drawer; thermometer and glassware on the shelf; bench and hotplate.
(define (problem lab-5)
  (:domain lab-bench)
  (:objects
    human - human
    robot - robot
    bench1 - bench
    hotplate1 - hotplate
    fridge1 - fridge
    drawer1 - drawer
    shelf1 - shelf
    buffer1 - buffer
    enzyme1 enzyme2 - enzyme
    culture1 - culture
    pipette1 - pipette
    thermometer1 - thermometer
    flask1 - flask
    beaker1 - beaker
    assay kinetics fermentation digestion hydrolysis - experiment
    red blue green - colour
    small large - size
    glass plastic - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human bench1)
    (at robot fridge1)
    (closed fridge1)
    (in buffer1 fridge1) (iscolour buffer1 blue) (issize buffer1 large) (ismaterial buffer1 plastic)
    (in enzyme1 fridge1) (iscolour enzyme1 red) (issize enzyme1 small) (ismaterial enzyme1 plastic)
    (in enzyme2 fridge1) (iscolour enzyme2 green) (issize enzyme2 large) (ismaterial enzyme2 plastic)
    (in culture1 fridge1) (iscolour culture1 red) (issize culture1 large) (ismaterial culture1 glass)
    (in pipette1 drawer1) (iscolour pipette1 green) (issize pipette1 small) (ismaterial pipette1 plastic)
    (in thermometer1 shelf1) (iscolour thermometer1 red) (issize thermometer1 small) (ismaterial thermometer1 glass)
    (in flask1 shelf1) (iscolour flask1 blue) (issize flask1 large) (ismaterial flask1 glass)
    (in beaker1 shelf1) (iscolour beaker1 green) (issize beaker1 small) (ismaterial beaker1 glass)
    (protocol assay buffer1 enzyme1 pipette1 bench1)
    (protocol kinetics buffer1 enzyme1 thermometer1 bench1)
    (protocol fermentation culture1 buffer1 flask1 hotplate1)
    (protocol digestion enzyme2 culture1 pipette1 hotplate1)
    (protocol hydrolysis enzyme2 buffer1 beaker1 hotplate1)
)
  (:goal (done assay))
)
