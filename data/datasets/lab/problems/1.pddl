; Acids and bases: a closed cabinet of reagents and an open shelf of glassware and water; bench and fume hood; five candidate experiments.
(define (problem lab-1)
  (:domain lab-bench)
  (:objects
    human - human
    robot - robot
    bench1 - bench
    hood1 - hood
    cabinet1 - cabinet
    shelf1 - shelf
    acid1 acid2 - acid
    base1 - base
    indicator1 - indicator
    burette1 - burette
    beaker1 - beaker
    pipette1 - pipette
    solvent1 - solvent
    titration standardisation neutralisation dilution dissolution - experiment
    red blue green - colour
    small large - size
    glass plastic - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human bench1)
    (at robot cabinet1)
    (closed cabinet1)
    (in acid1 cabinet1) (iscolour acid1 red) (issize acid1 large) (ismaterial acid1 glass)
    (in acid2 cabinet1) (iscolour acid2 blue) (issize acid2 small) (ismaterial acid2 plastic)
    (in base1 cabinet1) (iscolour base1 blue) (issize base1 large) (ismaterial base1 glass)
    (in indicator1 cabinet1) (iscolour indicator1 green) (issize indicator1 small) (ismaterial indicator1 glass)
    (in burette1 shelf1) (iscolour burette1 green) (issize burette1 large) (ismaterial burette1 glass)
    (in beaker1 shelf1) (iscolour beaker1 red) (issize beaker1 large) (ismaterial beaker1 glass)
    (in pipette1 shelf1) (iscolour pipette1 blue) (issize pipette1 small) (ismaterial pipette1 plastic)
    (in solvent1 shelf1) (iscolour solvent1 green) (issize solvent1 large) (ismaterial solvent1 plastic)
    (protocol titration acid1 indicator1 burette1 bench1)
    (protocol standardisation base1 indicator1 burette1 bench1)
    (protocol neutralisation acid1 base1 beaker1 hood1)
    (protocol dilution acid2 solvent1 pipette1 hood1)
    (protocol dissolution acid2 solvent1 beaker1 bench1)
)
  (:goal (done titration))
)
