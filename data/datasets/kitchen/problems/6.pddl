; Two cupboards, a large and a small one, all three containers closed: a
; large pan and a baking tray in the large cupboard, a small pan in the
; small one; the cheese is already on the counter. Every ingredient is in
; two dishes.
(define (problem kitchen-6)
  (:domain kitchen-recipes)
  (:objects
    human - human
    robot - robot
    counter1 - counter
    fridge1 - fridge
    cupboard1 cupboard2 - cupboard
    pantry1 - pantry
    egg1 - egg
    cheese1 - cheese
    potato1 - potato
    onion1 - onion
    pan1 pan2 - pan
    tray1 - tray
    omelette frittata gratin hash - dish
    small large - size
    red green yellow - colour
    glass metal wooden - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human counter1)
    (at robot cupboard2)
    (closed fridge1)
    (closed cupboard1)
    (closed cupboard2)
    (issize cupboard1 large) (issize cupboard2 small)
    (in egg1 fridge1) (issize egg1 small)
    (in cheese1 counter1) (issize cheese1 large) (iscolour cheese1 yellow)
    (in potato1 pantry1) (issize potato1 large)
    (in onion1 pantry1) (issize onion1 small) (iscolour onion1 red)
    (in pan1 cupboard1) (issize pan1 large) (iscolour pan1 red) (ismaterial pan1 metal)
    (in pan2 cupboard2) (issize pan2 small) (iscolour pan2 green) (ismaterial pan2 metal)
    (in tray1 cupboard1) (issize tray1 large) (ismaterial tray1 glass)
    (recipe2 omelette egg1 cheese1 pan2)
    (recipe2 frittata egg1 onion1 pan1)
    (recipe2 gratin potato1 cheese1 tray1)
    (recipe2 hash potato1 onion1 pan2))
  (:goal (made gratin))
)
