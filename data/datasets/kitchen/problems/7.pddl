; Only three places: everything is in the fridge or the cupboard, and both
; start closed. Two bowls, a large glass one and a small wooden one; eggs,
; sugar and cream in two dishes each.
(define (problem kitchen-7)
  (:domain kitchen-recipes)
  (:objects
    human - human
    robot - robot
    counter1 - counter
    fridge1 - fridge
    cupboard1 - cupboard
    egg1 - egg
    cream1 - cream
    butter1 - butter
    milk1 - milk
    sugar1 - sugar
    bowl1 bowl2 - bowl
    whisk1 - whisk
    pan1 - pan
    meringue mousse scramble milkshake - dish
    small large - size
    red green yellow - colour
    glass metal wooden - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human counter1)
    (at robot counter1)
    (closed fridge1)
    (closed cupboard1)
    (in egg1 fridge1) (issize egg1 small)
    (in cream1 fridge1) (issize cream1 small) (iscolour cream1 red)
    (in butter1 fridge1) (issize butter1 small) (iscolour butter1 yellow)
    (in milk1 fridge1) (issize milk1 large) (iscolour milk1 green)
    (in sugar1 cupboard1) (issize sugar1 small) (iscolour sugar1 red)
    (in bowl1 cupboard1) (issize bowl1 large) (ismaterial bowl1 glass)
    (in bowl2 cupboard1) (issize bowl2 small) (ismaterial bowl2 wooden)
    (in whisk1 cupboard1) (issize whisk1 small) (ismaterial whisk1 metal)
    (in pan1 cupboard1) (issize pan1 large) (iscolour pan1 red) (ismaterial pan1 metal)
    (recipe2 meringue egg1 sugar1 whisk1)
    (recipe2 mousse cream1 sugar1 bowl1)
    (recipe2 scramble egg1 butter1 pan1)
    (recipe2 milkshake milk1 cream1 bowl2))
  (:goal (made mousse))
)
