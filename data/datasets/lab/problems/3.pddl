; Organic chemistry: solvents, an acid and a base in a closed cabinet; flasks, a beaker and a thermometer on a shelf; fume hood and hotplate.
(define (problem lab-3)
  (:domain lab-bench)
  (:objects
    human - human
    robot - robot
    hood1 - hood
    hotplate1 - hotplate
    cabinet1 - cabinet
    shelf1 - shelf
    solvent1 solvent2 - solvent
    acid1 - acid
    base1 - base
    flask1 flask2 - flask
    beaker1 - beaker
    thermometer1 - thermometer
    distillation reflux extraction precipitation - experiment
    red blue green - colour
    small large - size
    glass plastic - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human hood1)
    (at robot shelf1)
    (closed cabinet1)
    (in solvent1 cabinet1) (iscolour solvent1 green) (issize solvent1 large) (ismaterial solvent1 glass)
    (in solvent2 cabinet1) (iscolour solvent2 red) (issize solvent2 small) (ismaterial solvent2 glass)
    (in acid1 cabinet1) (iscolour acid1 red) (issize acid1 small) (ismaterial acid1 plastic)
    (in base1 cabinet1) (iscolour base1 blue) (issize base1 large) (ismaterial base1 plastic)
    (in flask1 shelf1) (iscolour flask1 green) (issize flask1 large) (ismaterial flask1 glass)
    (in flask2 shelf1) (iscolour flask2 blue) (issize flask2 small) (ismaterial flask2 glass)
    (in beaker1 shelf1) (iscolour beaker1 red) (issize beaker1 large) (ismaterial beaker1 plastic)
    (in thermometer1 shelf1) (iscolour thermometer1 blue) (issize thermometer1 small) (ismaterial thermometer1 glass)
    (protocol distillation solvent1 acid1 flask1 hotplate1)
    (protocol reflux solvent2 acid1 thermometer1 hotplate1)
    (protocol extraction solvent2 base1 flask2 hood1)
    (protocol precipitation base1 solvent1 beaker1 hood1)
)
  (:goal (done distillation))
)
