; Sunday lunch: potatoes, onions and rice in two dishes each, one baking
; tray for two dishes, a red and a green pepper. Fridge and drawer start
; closed; the cupboard is open.
(define (problem kitchen-8)
  (:domain kitchen-recipes)
  (:objects
    human - human
    robot - robot
    counter1 - counter
    fridge1 - fridge
    cupboard1 - cupboard
    pantry1 - pantry
    drawer1 - drawer
    potato1 - potato
    onion1 - onion
    rice1 - rice
    cheese1 - cheese
    pepper1 pepper2 - pepper
    tray1 - tray
    pot1 - pot
    grater1 - grater
    roast gratin peppers pilaf - dish
    small large - size
    red green yellow - colour
    glass metal wooden - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human counter1)
    (at robot pantry1)
    (closed fridge1)
    (closed drawer1)
    (in potato1 pantry1) (issize potato1 large)
    (in onion1 pantry1) (issize onion1 small) (iscolour onion1 yellow)
    (in rice1 pantry1) (issize rice1 large) (iscolour rice1 green)
    (in cheese1 fridge1) (issize cheese1 small) (iscolour cheese1 yellow)
    (in pepper1 fridge1) (issize pepper1 large) (iscolour pepper1 red)
    (in pepper2 fridge1) (issize pepper2 small) (iscolour pepper2 green)
    (in tray1 cupboard1) (issize tray1 large) (ismaterial tray1 metal)
    (in pot1 cupboard1) (issize pot1 large) (ismaterial pot1 glass)
    (in grater1 drawer1) (issize grater1 small) (ismaterial grater1 metal)
    (recipe2 roast potato1 onion1 tray1)
    (recipe2 gratin potato1 cheese1 grater1)
    (recipe2 peppers pepper1 rice1 tray1)
    (recipe2 pilaf rice1 onion1 pot1))
  (:goal (made roast))
)
