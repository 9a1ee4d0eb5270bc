; Vegetables: a large red tomato and a small green one, a red onion that
; three dishes share. Only the fridge starts closed.
(define (problem kitchen-2)
  (:domain kitchen-recipes)
  (:objects
    human - human
    robot - robot
    counter1 - counter
    fridge1 - fridge
    cupboard1 - cupboard
    pantry1 - pantry
    drawer1 - drawer
    tomato1 tomato2 - tomato
    pepper1 - pepper
    onion1 - onion
    potato1 - potato
    knife1 - knife
    pot1 - pot
    bowl1 - bowl
    soup salsa salad stew - dish
    small large - size
    red green yellow - colour
    glass metal wooden - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human counter1)
    (at robot fridge1)
    (closed fridge1)
    (in tomato1 fridge1) (issize tomato1 large) (iscolour tomato1 red)
    (in tomato2 fridge1) (issize tomato2 small) (iscolour tomato2 green)
    (in pepper1 fridge1) (issize pepper1 large) (iscolour pepper1 yellow)
    (in onion1 pantry1) (issize onion1 small) (iscolour onion1 red)
    (in potato1 pantry1) (issize potato1 large)
    (in knife1 drawer1) (issize knife1 small) (ismaterial knife1 metal)
    (in pot1 cupboard1) (issize pot1 large) (ismaterial pot1 metal)
    (in bowl1 cupboard1) (issize bowl1 small) (ismaterial bowl1 wooden)
    (recipe2 soup tomato1 onion1 pot1)
    (recipe3 salsa tomato1 onion1 pepper1 knife1)
    (recipe2 salad tomato2 pepper1 bowl1)
    (recipe2 stew potato1 onion1 pot1))
  (:goal (made soup))
)
