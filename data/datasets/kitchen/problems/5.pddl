; Fruit: a banana and a lemon that two dishes each share, two apples, a
; large metal knife and a small wooden one; the sugar is already on the
; counter. Fridge and drawer start closed; no cupboard.
(define (problem kitchen-5)
  (:domain kitchen-recipes)
  (:objects
    human - human
    robot - robot
    counter1 - counter
    fridge1 - fridge
    pantry1 - pantry
    drawer1 - drawer
    apple1 apple2 - apple
    banana1 - banana
    lemon1 - lemon
    milk1 - milk
    sugar1 - sugar
    knife1 knife2 - knife
    spoon1 - spoon
    fruitsalad smoothie lemonade applesauce - dish
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
    (closed drawer1)
    (in apple1 pantry1) (issize apple1 large) (iscolour apple1 red)
    (in apple2 pantry1) (issize apple2 small) (iscolour apple2 green)
    (in banana1 pantry1) (issize banana1 large) (iscolour banana1 yellow)
    (in lemon1 fridge1) (issize lemon1 small) (iscolour lemon1 yellow)
    (in milk1 fridge1) (issize milk1 large) (iscolour milk1 red)
    (in sugar1 counter1) (issize sugar1 small) (iscolour sugar1 green)
    (in knife1 drawer1) (issize knife1 large) (ismaterial knife1 metal)
    (in knife2 drawer1) (issize knife2 small) (ismaterial knife2 wooden)
    (in spoon1 drawer1) (issize spoon1 small) (ismaterial spoon1 metal)
    (recipe2 fruitsalad apple1 banana1 knife1)
    (recipe2 smoothie banana1 milk1 spoon1)
    (recipe2 lemonade lemon1 sugar1 spoon1)
    (recipe2 applesauce apple2 lemon1 knife2))
  (:goal (made fruitsalad))
)
