; Biology: enzymes, a buffer, a culture and a stain in a closed fridge; pipettes and a thermometer in a drawer; bench and hotplate.
(define (problem lab-2)
  (:domain lab-bench)
  (:objects
    human - human
    robot - robot
    bench1 - bench
    hotplate1 - hotplate
    fridge1 - fridge
    drawer1 - drawer
    enzyme1 enzyme2 - enzyme
    buffer1 - buffer
    culture1 - culture
    indicator1 - indicator
    pipette1 pipette2 - pipette
    thermometer1 - thermometer
    assay digestion incubation staining lysis - experiment
    red blue green - colour
    small large - size
    glass plastic - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human bench1)
    (at robot drawer1)
    (closed fridge1)
    (in enzyme1 fridge1) (iscolour enzyme1 red) (issize enzyme1 small) (ismaterial enzyme1 plastic)
    (in enzyme2 fridge1) (iscolour enzyme2 blue) (issize enzyme2 small) (ismaterial enzyme2 plastic)
    (in buffer1 fridge1) (iscolour buffer1 blue) (issize buffer1 large) (ismaterial buffer1 plastic)
    (in culture1 fridge1) (iscolour culture1 green) (issize culture1 small) (ismaterial culture1 glass)
    (in indicator1 fridge1) (iscolour indicator1 green) (issize indicator1 large) (ismaterial indicator1 glass)
    (in pipette1 drawer1) (iscolour pipette1 blue) (issize pipette1 small) (ismaterial pipette1 plastic)
    (in pipette2 drawer1) (iscolour pipette2 green) (issize pipette2 large) (ismaterial pipette2 plastic)
    (in thermometer1 drawer1) (iscolour thermometer1 red) (issize thermometer1 small) (ismaterial thermometer1 glass)
    (protocol assay enzyme1 buffer1 pipette1 bench1)
    (protocol digestion enzyme2 culture1 pipette2 hotplate1)
    (protocol incubation culture1 buffer1 thermometer1 hotplate1)
    (protocol staining culture1 indicator1 pipette2 bench1)
    (protocol lysis enzyme1 culture1 thermometer1 hotplate1)
)
  (:goal (done assay))
)
