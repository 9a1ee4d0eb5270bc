; Two acids of different sizes in a closed cabinet; a pipette and a thermometer in a drawer; a burette and a beaker on a shelf; bench and fume hood; five candidate experiments.
(define (problem lab-6)
  (:domain lab-bench)
  (:objects
    human - human
    robot - robot
    bench1 - bench
    hood1 - hood
    cabinet1 - cabinet
    drawer1 - drawer
    shelf1 - shelf
    acid1 acid2 - acid
    indicator1 - indicator
    solvent1 - solvent
    base1 - base
    pipette1 - pipette
    thermometer1 - thermometer
    burette1 - burette
    beaker1 - beaker
    titration dilution calibration neutralisation distillation - experiment
    red blue green - colour
    small large - size
    glass plastic - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human bench1)
    (at robot shelf1)
    (closed cabinet1)
    (in acid1 cabinet1) (iscolour acid1 red) (issize acid1 small) (ismaterial acid1 glass)
    (in acid2 cabinet1) (iscolour acid2 red) (issize acid2 large) (ismaterial acid2 glass)
    (in indicator1 cabinet1) (iscolour indicator1 green) (issize indicator1 small) (ismaterial indicator1 plastic)
    (in solvent1 cabinet1) (iscolour solvent1 blue) (issize solvent1 large) (ismaterial solvent1 plastic)
    (in base1 cabinet1) (iscolour base1 green) (issize base1 large) (ismaterial base1 plastic)
    (in pipette1 drawer1) (iscolour pipette1 blue) (issize pipette1 small) (ismaterial pipette1 plastic)
    (in thermometer1 drawer1) (iscolour thermometer1 green) (issize thermometer1 small) (ismaterial thermometer1 glass)
    (in burette1 shelf1) (iscolour burette1 blue) (issize burette1 large) (ismaterial burette1 glass)
    (in beaker1 shelf1) (iscolour beaker1 red) (issize beaker1 small) (ismaterial beaker1 glass)
    (protocol titration acid2 indicator1 burette1 bench1)
    (protocol dilution acid1 solvent1 burette1 hood1)
    (protocol calibration indicator1 solvent1 thermometer1 bench1)
    (protocol neutralisation acid1 base1 beaker1 hood1)
    (protocol distillation acid2 solvent1 thermometer1 hood1)
)
  (:goal (done titration))
)
