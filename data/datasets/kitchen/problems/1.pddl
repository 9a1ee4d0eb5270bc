; Breakfast: an egg in every dish, two pans of different sizes; the sugar
; is already on the counter. Fridge and cupboard start closed.
(define (problem kitchen-1)
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
    milk1 - milk
    egg1 - egg
    cheese1 - cheese
    pan1 pan2 - pan
    bowl1 - bowl
    whisk1 - whisk
    pancakes custard omelette cake - dish
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
    (in flour1 pantry1) (issize flour1 large) (iscolour flour1 yellow)
    (in sugar1 counter1) (issize sugar1 small) (iscolour sugar1 red)
    (in milk1 fridge1) (issize milk1 large) (iscolour milk1 green)
    (in egg1 fridge1) (issize egg1 small)
    (in cheese1 fridge1) (issize cheese1 small) (iscolour cheese1 yellow)
    (in pan1 cupboard1) (issize pan1 large) (iscolour pan1 red) (ismaterial pan1 metal)
    (in pan2 cupboard1) (issize pan2 small) (iscolour pan2 green) (ismaterial pan2 metal)
    (in bowl1 cupboard1) (issize bowl1 large) (iscolour bowl1 green) (ismaterial bowl1 glass)
    (in whisk1 drawer1) (issize whisk1 small) (ismaterial whisk1 metal)
    (recipe3 pancakes flour1 milk1 egg1 pan1)
    (recipe3 custard milk1 egg1 sugar1 whisk1)
    (recipe2 omelette egg1 cheese1 pan2)
    (recipe3 cake flour1 egg1 sugar1 bowl1))
  (:goal (made pancakes))
)
