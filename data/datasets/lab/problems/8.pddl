; Six places: bench, fume hood (a solvent already in it), hotplate, a closed cabinet, a closed fridge and a shelf; five candidate experiments.
(define (problem lab-8)
  (:domain lab-bench)
  (:objects
    human - human
    robot - robot
    bench1 - bench
    hood1 - hood
    hotplate1 - hotplate
    cabinet1 - cabinet
    fridge1 - fridge
    shelf1 - shelf
    solvent1 - solvent
    acid1 - acid
    base1 - base
    serum1 - serum
    culture1 - culture
    buffer1 - buffer
    beaker1 - beaker
    flask1 - flask
    pipette1 - pipette
    extraction neutralisation assay fermentation precipitation - experiment
    red blue green - colour
    small large - size
    glass plastic - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human bench1)
    (at robot fridge1)
    (closed cabinet1)
    (closed fridge1)
    (in solvent1 hood1) (iscolour solvent1 green) (issize solvent1 large) (ismaterial solvent1 glass)
    (in acid1 cabinet1) (iscolour acid1 red) (issize acid1 large) (ismaterial acid1 glass)
    (in base1 cabinet1) (iscolour base1 blue) (issize base1 small) (ismaterial base1 plastic)
    (in serum1 fridge1) (iscolour serum1 blue) (issize serum1 small) (ismaterial serum1 plastic)
    (in culture1 fridge1) (iscolour culture1 red) (issize culture1 small) (ismaterial culture1 plastic)
    (in buffer1 fridge1) (iscolour buffer1 green) (issize buffer1 large) (ismaterial buffer1 plastic)
    (in beaker1 shelf1) (iscolour beaker1 blue) (issize beaker1 large) (ismaterial beaker1 glass)
    (in flask1 shelf1) (iscolour flask1 red) (issize flask1 small) (ismaterial flask1 glass)
    (in pipette1 shelf1) (iscolour pipette1 green) (issize pipette1 small) (ismaterial pipette1 plastic)
    (protocol extraction solvent1 culture1 flask1 hood1)
    (protocol neutralisation acid1 base1 beaker1 hood1)
    (protocol assay serum1 buffer1 pipette1 bench1)
    (protocol fermentation culture1 buffer1 flask1 hotplate1)
    (protocol precipitation serum1 acid1 beaker1 bench1)
)
  (:goal (done extraction))
)
