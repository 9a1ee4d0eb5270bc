; A buffer already on the bench and a solvent already in the fume hood; samples and an enzyme in a closed fridge; pipettes and a beaker on a shelf; five candidate experiments.
(define (problem lab-4)
  (:domain lab-bench)
  (:objects
    human - human
    robot - robot
    bench1 - bench
    hood1 - hood
    fridge1 - fridge
    shelf1 - shelf
    buffer1 - buffer
    solvent1 - solvent
    enzyme1 - enzyme
    serum1 - serum
    culture1 - culture
    pipette1 pipette2 - pipette
    beaker1 - beaker
    assay immunoassay extraction precipitation digestion - experiment
    red blue green - colour
    small large - size
    glass plastic - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human shelf1)
    (at robot fridge1)
    (closed fridge1)
    (in buffer1 bench1) (iscolour buffer1 blue) (issize buffer1 large) (ismaterial buffer1 plastic)
    (in solvent1 hood1) (iscolour solvent1 green) (issize solvent1 large) (ismaterial solvent1 glass)
    (in enzyme1 fridge1) (iscolour enzyme1 red) (issize enzyme1 small) (ismaterial enzyme1 plastic)
    (in serum1 fridge1) (iscolour serum1 blue) (issize serum1 small) (ismaterial serum1 glass)
    (in culture1 fridge1) (iscolour culture1 green) (issize culture1 small) (ismaterial culture1 plastic)
    (in pipette1 shelf1) (iscolour pipette1 red) (issize pipette1 small) (ismaterial pipette1 plastic)
    (in pipette2 shelf1) (iscolour pipette2 blue) (issize pipette2 large) (ismaterial pipette2 plastic)
    (in beaker1 shelf1) (iscolour beaker1 green) (issize beaker1 large) (ismaterial beaker1 glass)
    (protocol assay buffer1 enzyme1 pipette1 bench1)
    (protocol immunoassay buffer1 serum1 pipette2 bench1)
    (protocol extraction solvent1 culture1 beaker1 hood1)
    (protocol precipitation solvent1 serum1 pipette1 hood1)
    (protocol digestion enzyme1 culture1 beaker1 hood1)
)
  (:goal (done assay))
)
