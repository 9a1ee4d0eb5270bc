; Grains and dairy: rice in two dishes, milk in two, a large metal pot and
; a small glass one; the sugar is already on the counter. Fridge and
; cupboard start closed; no drawer.
(define (problem kitchen-4)
  (:domain kitchen-recipes)
  (:objects
    human - human
    robot - robot
    counter1 - counter
    fridge1 - fridge
    cupboard1 - cupboard
    pantry1 - pantry
    milk1 - milk
    cheese1 - cheese
    cream1 - cream
    rice1 - rice
    oats1 - oats
    sugar1 - sugar
    pot1 pot2 - pot
    pan1 - pan
    porridge risotto pudding sauce - dish
    small large - size
    red green yellow - colour
    glass metal wooden - material)
  (:init
    (active human)
    (next-turn human robot)
    (next-turn robot human)
    (at human counter1)
    (at robot cupboard1)
    (closed fridge1)
    (closed cupboard1)
    (in milk1 fridge1) (issize milk1 large) (iscolour milk1 green)
    (in cheese1 fridge1) (issize cheese1 small) (iscolour cheese1 yellow)
    (in cream1 fridge1) (issize cream1 small) (iscolour cream1 red)
    (in rice1 pantry1) (issize rice1 large) (iscolour rice1 green)
    (in oats1 pantry1) (issize oats1 small) (iscolour oats1 yellow)
    (in sugar1 counter1) (issize sugar1 small) (iscolour sugar1 red)
    (in pot1 cupboard1) (issize pot1 large) (ismaterial pot1 metal)
    (in pot2 cupboard1) (issize pot2 small) (ismaterial pot2 glass)
    (in pan1 cupboard1) (issize pan1 large) (iscolour pan1 red) (ismaterial pan1 metal)
    (recipe2 porridge oats1 milk1 pot2)
    (recipe2 risotto rice1 cheese1 pot1)
    (recipe3 pudding rice1 milk1 sugar1 pot1)
    (recipe2 sauce cheese1 cream1 pan1))
  (:goal (made risotto))
)
