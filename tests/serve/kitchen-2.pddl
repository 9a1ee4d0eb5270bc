; The kitchen of docs/domains.md, problem 2: the cook at the counter, the helper
; in the pantry. No plan has ever been recorded for it (tests of sessions on
; problems without plans: pack_sessions_test.cpp, loopback_test.cpp, browser_e2e.py).
(define (problem kitchen-2)
  (:domain kitchen)
  (:objects
    cook - cook
    helper - helper
    counter fridge pantry - place
    flour1 - flour
    sugar1 - sugar
    milk1 - milk
    butter1 - butter
    cake cookies fudge pudding - dish
    cold warm - temperature)
  (:init
    (counter counter)
    (at cook counter) (at helper pantry)
    (in flour1 pantry) (istemp flour1 warm)
    (in sugar1 pantry) (istemp sugar1 warm)
    (in milk1 fridge) (istemp milk1 cold)
    (in butter1 fridge) (istemp butter1 cold)
    (recipe cake flour1 milk1)
    (recipe cookies flour1 butter1)
    (recipe fudge sugar1 butter1)
    (recipe pudding sugar1 milk1)))
