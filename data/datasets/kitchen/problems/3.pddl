; Baking: flour in three dishes, sugar in two; a red apple already on the
; counter and a green one in the fridge; a metal and a glass baking tray,
; and a glass bowl that no dish needs. Fridge and cupboard start closed.
(define (problem kitchen-3)
  (:domain kitchen-recipes)
  (:objects
    human - human
    robot - robot
    counter1 - counter
    fridge1 - fridge
    cupboard1 - cupboard
    pantry1 - pantry
    drawer1 - drawer
    flour1 - flour
    sugar1 - sugar
    butter1 - butter
    apple1 apple2 - apple
    tray1 tray2 - tray
    bowl1 - bowl
    spoon1 - spoon
    crumble pie biscuits compote - dish
    small large - size
    red green yellow - colour
    glass metal wooden - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human pantry1)
    (at robot fridge1)
    (closed fridge1)
    (closed cupboard1)
    (in flour1 pantry1) (issize flour1 large) (iscolour flour1 yellow)
    (in sugar1 pantry1) (issize sugar1 small) (iscolour sugar1 red)
    (in butter1 fridge1) (issize butter1 small) (iscolour butter1 yellow)
    (in apple1 counter1) (issize apple1 large) (iscolour apple1 red)
    (in apple2 fridge1) (issize apple2 small) (iscolour apple2 green)
    (in tray1 cupboard1) (issize tray1 large) (ismaterial tray1 metal)
    (in tray2 cupboard1) (issize tray2 small) (ismaterial tray2 glass)
    (in bowl1 cupboard1) (issize bowl1 large) (ismaterial bowl1 glass)
    (in spoon1 drawer1) (issize spoon1 small) (ismaterial spoon1 wooden)
    (recipe3 crumble apple1 flour1 butter1 tray1)
    (recipe3 pie apple2 flour1 butter1 tray2)
    (recipe2 biscuits flour1 sugar1 tray1)
    (recipe2 compote apple2 sugar1 spoon1))
  (:goal (made crumble))
)
