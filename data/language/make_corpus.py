#!/usr/bin/env python3
"""Writes corpus-dkg.tsv and corpus-vh.tsv: command<TAB>utterance training pairs
for the embedded language model (src/lm/embedded_model.hpp).

All phrasings below were written for this corpus (none is taken from the CLIPS
dataset). Sentences are produced by combining hand-written request frames, verb
phrases and noun phrases for every command shape the CLIPS enumeration produces,
plus a list of free-standing sentences. Deterministic (fixed seed).

Usage: python3 make_corpus.py   (run from any directory; writes next to this file)
"""
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
rng = random.Random(20240517)

COLOURS = ["red", "blue", "yellow", "green"]
RARE_COLOURS = ["purple", "orange", "white", "pink"]


def colour():
    return rng.choice(COLOURS) if rng.random() < 0.9 else rng.choice(RARE_COLOURS)


def two_colours():
    a = colour()
    b = colour()
    while b == a:
        b = colour()
    return a, b


def cap(s):
    return s[0].upper() + s[1:]


# --------------------------------------------------------------------------- frames
# A request frame wraps a verb phrase. {vp} is lower-case.
REQUEST_FRAMES = [
    "Can you {vp}?", "Could you {vp}?", "Would you {vp}?", "Please {vp}.", "{VP}.",
    "{VP}, please.", "Can you please {vp}?", "Could you please {vp}?", "Will you {vp}?",
    "I'd like you to {vp}.", "Mind if I ask you to {vp}?", "Hey, can you {vp}?", "{VP} for me.",
    "Go {vp}.", "Do you think you could {vp}?", "Can you help me and {vp}?", "Quick, {vp}!",
    "Would you be able to {vp}?", "Robot, {vp}.", "If you can, {vp}.", "I need you to {vp}.",
    "Try to {vp}.", "Let's have you {vp}.", "Your job: {vp}.",
]


def request(vp, action=None):
    f = rng.choice(REQUEST_FRAMES)
    while f == "{VP} for me." and action == "pickup":
        f = rng.choice(REQUEST_FRAMES)
    if f == "Go {vp}." and not vp.split()[0] in ("get", "grab", "fetch", "find", "pick", "open", "unlock"):
        f = "{VP}."
    if f == "{VP} for me." and ("me" in vp.split() or "for me" in vp):
        f = "{VP}."
    return f.replace("{vp}", vp).replace("{VP}", cap(vp))


# ------------------------------------------------------------------------- mDKG parts
def key_np(c, n=1, det=None):
    """Noun phrase for n keys of colour c (c may be None)."""
    cc = (c + " ") if c else ""
    if n == 1:
        d = det or rng.choice(["the", "the", "the", "a", "that", "this", "one"])
        if d == "one":
            return f"one {cc}key" if c else "one key"
        return f"{d} {cc}key"
    if n == 2:
        return rng.choice([f"both {cc}keys", f"the two {cc}keys", f"two {cc}keys", f"the {cc}keys",
                           f"a pair of {cc}keys", f"both of the {cc}keys", f"those two {cc}keys",
                           f"these {cc}keys", f"a couple of {cc}keys"])
    return rng.choice([f"three {cc}keys", f"all three {cc}keys", f"the three {cc}keys",
                       f"all the {cc}keys", f"all of the {cc}keys", f"these three {cc}keys"])


def door_np(c, n=1):
    cc = (c + " ") if c else ""
    if n == 1:
        return rng.choice([f"the {cc}door", f"the {cc}door", f"that {cc}door", f"this {cc}door",
                           f"the {cc}door over there", f"the {cc}door ahead"])
    if n == 2:
        return rng.choice([f"both {cc}doors", f"the two {cc}doors", f"two {cc}doors", f"the {cc}doors",
                           f"those {cc}doors", f"these two {cc}doors"])
    return rng.choice([f"three {cc}doors", f"all three {cc}doors", f"the three {cc}doors",
                       f"all the {cc}doors", f"these three {cc}doors"])


def mixed_np(noun, cols):
    """Two different colours of the same noun."""
    a, b = cols
    return rng.choice([f"the {a} and {b} {noun}s", f"the {a} {noun} and the {b} {noun}",
                       f"the {a} {noun} and the {b} one", f"a {a} {noun} and a {b} {noun}",
                       f"the {a} and the {b} {noun}", f"one {a} {noun} and one {b} {noun}",
                       f"both the {a} {noun} and the {b} {noun}"])


PICKUP_VERBS = ["pick up {np}", "grab {np}", "get {np}", "go get {np}", "fetch {np}", "collect {np}",
                "take {np}", "go and pick up {np}", "find {np}", "look for {np}", "go find {np}",
                "retrieve {np}", "pick {np} up", "go grab {np}", "snag {np}", "head over and get {np}",
                "go collect {np}", "obtain {np}", "nab {np}", "go and take {np}", "get hold of {np}",
                "search for {np}", "go after {np}", "go for {np}"]
HANDOVER_VERBS = ["pass me {np}", "hand me {np}", "give me {np}", "bring me {np}", "get me {np}",
                  "fetch me {np}", "grab me {np}", "bring {np} to me", "hand {np} over",
                  "pass {np} over to me", "hand over {np}", "give {np} to me", "find me {np}",
                  "get {np} for me", "bring {np} over here", "bring {np} here", "deliver {np} to me",
                  "toss me {np}", "send {np} my way", "pick up {np} and bring it to me",
                  "get {np} and give it to me", "fetch {np} for me", "look for {np} and bring it here",
                  "pass over {np}", "bring me back {np}", "go get me {np}", "grab {np} for me",
                  "go grab me {np}", "grab me {np}", "find {np} for me", "look for {np} for me",
                  "find me {np}", "get me {np}"]
HANDOVER_STATEMENTS = ["I need {np}.", "I want {np}.", "Can I have {np}?", "Let me have {np}.",
                       "I could use {np}.", "I'd like {np}.", "May I have {np}?", "I need {np}, please.",
                       "{NP} for me, please.", "Could I get {np}?", "I'm looking for {np}, can you help?",
                       "Help me get {np}."]
UNLOCK_VERBS = ["open {np}", "unlock {np}", "get {np} open", "get {np}", "deal with {np}",
                "take care of {np}", "unlock {np} for me", "open up {np}", "clear {np}",
                "use a key on {np}", "get {np} unlocked", "handle {np}", "open {np} for me",
                "help me through {np}", "help me open {np}", "help me with {np}", "unlock {np} please",
                "go open {np}", "get me through {np}", "use your key on {np}", "work on {np}",
                "open {np} up", "break through {np}", "let me through {np}"]
UNLOCK_STATEMENTS = ["I need {np} open.", "I need {np} unlocked.", "{NP} needs to be opened.",
                     "Help me get past {np}.", "I can't get through {np}.", "Let me through {np}.",
                     "{NP} is locked, can you open it?", "I need to get through {np}."]


def pronoun_fix(vp, n):
    return vp.replace("bring it", "bring them").replace("give it", "give them") if n > 1 else vp


def vp_for(action, np, n=1):
    if action == "pickup":
        return pronoun_fix(rng.choice(PICKUP_VERBS).format(np=np), n)
    if action == "handover":
        return pronoun_fix(rng.choice(HANDOVER_VERBS).format(np=np), n)
    return rng.choice(UNLOCK_VERBS).format(np=np)


def single_sentence(action, np, n=1):
    """A whole utterance for one group."""
    r = rng.random()
    if action == "handover" and r < 0.22:
        s = rng.choice(HANDOVER_STATEMENTS)
        return s.replace("{NP}", cap(np)).replace("{np}", np)
    if action == "unlock" and r < 0.18:
        s = rng.choice(UNLOCK_STATEMENTS)
        return s.replace("{NP}", cap(np)).replace("{np}", np)
    return request(vp_for(action, np, n), action)


class Cmd:
    """Builds lifted mDKG commands in the printed LLM form."""

    def __init__(self):
        self.acts = []
        self.preds = []
        self.counter = {}

    def var(self, t):
        self.counter[t] = self.counter.get(t, 0) + 1
        return f"{t}{self.counter[t]}"

    def add(self, action, col, agent="you"):
        if action == "pickup":
            k = self.var("key")
            self.acts.append(f"(pickup {agent} {k})")
            focal = k
        elif action == "handover":
            k = self.var("key")
            self.acts.append(f"(handover you me {k})")
            focal = k
        elif action == "gem":
            g = self.var("gem")
            self.acts.append(f"(pickup {agent} {g})")
            focal = g
        else:
            k = self.var("key")
            d = self.var("door")
            self.acts.append(f"(unlock {agent} {k} {d})")
            focal = d
        if col:
            self.preds.append(f"(iscolor {focal} {col})")
        return focal

    def text(self):
        s = " ".join(self.acts)
        if self.preds:
            s += " where " + " ".join(self.preds)
        return s


def np_for(action, col, n):
    return door_np(col, n) if action == "unlock" else key_np(col, n)


def dkg_single(rows, count):
    for _ in range(count):
        action = rng.choice(["pickup", "handover", "handover", "unlock"])
        col = colour() if rng.random() < 0.92 else None
        c = Cmd()
        c.add(action, col)
        rows.append((c.text(), single_sentence(action, np_for(action, col, 1))))


def dkg_same_colour_group(rows, count, n):
    for _ in range(count):
        action = rng.choice(["pickup", "handover", "handover", "unlock"])
        col = colour() if rng.random() < 0.9 else None
        c = Cmd()
        for _ in range(n):
            c.add(action, col)
        rows.append((c.text(), single_sentence(action, np_for(action, col, n), n)))


def dkg_two_colours(rows, count):
    for _ in range(count):
        action = rng.choice(["pickup", "handover", "handover", "unlock"])
        cols = two_colours()
        c = Cmd()
        c.add(action, cols[0])
        c.add(action, cols[1])
        np = mixed_np("door" if action == "unlock" else "key", cols)
        rows.append((c.text(), single_sentence(action, np, 2)))


JOINERS = ["{a} and {b}", "{a}, then {b}", "{a} and also {b}", "first {a}, then {b}", "{a}, and {b}",
           "{a} and after that {b}", "{a}; also {b}"]


def joined_request(vpa, vpb):
    j = rng.choice(JOINERS).format(a=vpa, b=vpb)
    return request(j)


def dkg_mixed(rows, count):
    """Two or three actions of two different kinds, e.g. unlock + handover."""
    kinds = ["pickup", "handover", "unlock"]
    for _ in range(count):
        a, b = rng.sample(kinds, 2)
        na = 2 if rng.random() < 0.25 else 1
        ca, cb = colour(), colour()
        if rng.random() < 0.1:
            ca = cb = None
        c = Cmd()
        order = [(a, ca)] * na + [(b, cb)]
        if rng.random() < 0.4:
            order = [(b, cb)] + [(a, ca)] * na
        for act, col in order:
            c.add(act, col)
        first, second = order[0], order[-1]
        n_first = na if first[0] == a else 1
        n_second = na if second[0] == a else 1
        vpa = vp_for(first[0], np_for(first[0], first[1], n_first), n_first)
        vpb = vp_for(second[0], np_for(second[0], second[1], n_second), n_second)
        rows.append((c.text(), joined_request(vpa, vpb)))


CHAIN = ["pick up the {c} key and bring it to me", "grab the {c} key and hand it to me",
         "get the {c} key and pass it over", "collect the {c} key and give it to me",
         "pick up the {c} key, then hand it over", "take the {c} key and bring it here"]


def dkg_chain(rows, count):
    for _ in range(count):
        col = colour()
        cmd = f"(pickup you key1) (handover you me key1) where (iscolor key1 {col}) (iscolor key1 {col})"
        rows.append((cmd, request(rng.choice(CHAIN).format(c=col))))


# Statements about the speaker's own part.
SELF_KEY = ["I'll get {np}", "I will grab {np}", "I'm getting {np}", "I'm going for {np}",
            "I'll take care of {np}", "let me get {np}", "I can pick up {np} myself", "I'll pick up {np}",
            "I'm grabbing {np}", "I've got {np}", "I'll go for {np}", "I'm heading for {np}",
            "I'm picking up {np}", "I will get {np} myself", "I'll handle {np}"]
SELF_DOOR = ["I'll open {np}", "I'm unlocking {np}", "I will take care of {np}", "let me open {np}",
             "I'll handle {np}"]


def self_clause(kind, col, n=1):
    if kind == "unlock":
        return rng.choice(SELF_DOOR).format(np=door_np(col, n))
    if kind == "gem":
        cc = (col + " ") if col else ""
        return rng.choice(SELF_KEY).format(np=rng.choice([f"the {cc}gem", f"that {cc}gem", f"the {cc}jewel"]))
    return rng.choice(SELF_KEY).format(np=key_np(col, n, det="the") if n == 1 else key_np(col, n))


def one_np(action, col):
    """Anaphoric noun phrase used after a first mention ("the blue one")."""
    if rng.random() < 0.5:
        return f"the {col} one" if col else "the other one"
    return np_for(action, col, 1)


def joint(rows, count):
    """Speaker + listener commands, with and without the speaker's action in the command."""
    for _ in range(count):
        you_act = rng.choice(["pickup", "handover", "handover", "unlock"])
        me_act = rng.choice(["pickup", "pickup", "gem", "unlock"])
        c_you, c_me = two_colours()
        n_you = 2 if rng.random() < 0.2 else 1
        self_part = self_clause(me_act, c_me)
        np = np_for(you_act, c_you, n_you) if n_you > 1 else one_np(you_act, c_you)
        if you_act == "unlock" and n_you == 1:
            np = door_np(c_you)
        vp = vp_for(you_act, np, n_you)
        style = rng.random()
        if style < 0.4:
            utt = f"{cap(self_part)}, {rng.choice(['can you', 'could you', 'would you', 'you'])} {vp}?"
        elif style < 0.7:
            utt = f"{cap(request(vp)).rstrip('.?!')}? {cap(self_part)}."
        elif style < 0.85:
            utt = f"{cap(vp)} while {self_part.replace('let me', 'I')}."
        else:
            utt = f"{cap(self_part)} and you {vp}."
        # Listener-only command: the form the CLIPS enumeration produces.
        c = Cmd()
        for _ in range(n_you):
            c.add(you_act, c_you)
        rows.append((c.text(), utt))
        # Joint command (the form of the few-shot examples), half of the time.
        if rng.random() < 0.5:
            c2 = Cmd()
            if rng.random() < 0.5:
                c2.add(me_act if me_act != "unlock" else "unlock", c_me, agent="me")
                for _ in range(n_you):
                    c2.add(you_act, c_you)
            else:
                for _ in range(n_you):
                    c2.add(you_act, c_you)
                c2.add(me_act, c_me, agent="me")
            rows.append((c2.text(), utt))


DKG_FREE = [
    ("(pickup you key1)", "Grab that key over there."),
    ("(pickup you key1)", "Could you pick up the key near you?"),
    ("(pickup you key1)", "Go get the key in the corner."),
    ("(handover you me key1)", "Bring that key over to me."),
    ("(handover you me key1)", "Could you give me a key?"),
    ("(handover you me key1)", "I need a key, can you bring me one?"),
    ("(unlock you key1 door1)", "Open that door for me."),
    ("(unlock you key1 door1)", "Can you get this door open?"),
    ("(unlock you key1 door1) (unlock you key2 door2)", "Please open both of these doors."),
    ("(unlock you key1 door1) (handover you me key2)", "Open the door, then hand me a key."),
    ("(handover you me key1) where (iscolor key1 blue)", "I need a key for the blue door."),
    ("(handover you me key1) where (iscolor key1 red)", "Bring me the key that opens the red door."),
    ("(handover you me key1) where (iscolor key1 green)", "Find me a key for that green door."),
    ("(handover you me key1) where (iscolor key1 yellow)", "Get me something to open the yellow door."),
    ("(unlock you key1 door1) where (iscolor door1 blue)", "Find a key for the blue door and open it."),
    ("(unlock you key1 door1) where (iscolor door1 red)", "Use the key you have on the red door."),
    ("(pickup you key1) where (iscolor key1 green)", "Can you find a key for this green door?"),
    ("(unlock you key1 door1) where (iscolor door1 yellow)", "The yellow door is in my way."),
    ("(unlock you key1 door1) where (iscolor door1 red)", "Get the red door for me."),
    ("(unlock you key1 door1) where (iscolor door1 blue)", "Get that blue door."),
    ("(pickup you key1) where (iscolor key1 red)", "Red key, please."),
    ("(handover you me key1) where (iscolor key1 blue)", "Blue key to me, please."),
    ("(handover you me key1) (handover you me key2) where (iscolor key1 red) (iscolor key2 red)",
     "I need both red keys."),
    ("(handover you me key1) (handover you me key2) where (iscolor key1 blue) (iscolor key2 blue)",
     "Two blue keys for me, please."),
    ("(pickup you key1) (pickup you key2) where (iscolor key1 yellow) (iscolor key2 yellow)",
     "Collect both of the yellow keys."),
    ("(unlock you key1 door1) (unlock you key2 door2) where (iscolor door1 red) (iscolor door2 red)",
     "Both red doors need opening."),
    ("(handover you me key1) where (iscolor key1 green)", "Hand the green key over, would you?"),
    ("(handover you me key1) where (iscolor key1 yellow)", "Pass the yellow key my way."),
    ("(pickup you key1) where (iscolor key1 blue)", "Pick the blue key up off the floor."),
    ("(handover you me key1) where (iscolor key1 red)", "Could you grab me the key that's red?"),
]


KEY_FOR_DOOR = ["bring me a key for the {c} door", "find me the key that opens the {c} door",
                "get me a key for that {c} door", "hand me the key for the {c} door",
                "I need a key that fits the {c} door", "pass me a key that works on the {c} door",
                "give me something that opens the {c} door", "fetch me the {c} door's key"]
PICK_KEY_FOR_DOOR = ["pick up a key for the {c} door", "grab the key that opens the {c} door",
                     "go get a key for the {c} door", "find the key for that {c} door"]
OPEN_WITH_KEY = ["use the {c} key on the {c} door", "take a key and open the {c} door",
                 "find a key and unlock the {c} door", "get a key for the {c} door and open it",
                 "grab a key and get the {c} door open"]


def dkg_key_for_door(rows, count):
    # Keys open doors of their own colour, so "a key for the blue door" names a blue key.
    for _ in range(count):
        col = colour()
        r = rng.random()
        if r < 0.45:
            s = rng.choice(KEY_FOR_DOOR).format(c=col)
            utt = s[0].upper() + s[1:] + "." if s.startswith("I ") else request(s)
            rows.append((f"(handover you me key1) where (iscolor key1 {col})", utt))
        elif r < 0.65:
            rows.append((f"(pickup you key1) where (iscolor key1 {col})",
                         request(rng.choice(PICK_KEY_FOR_DOOR).format(c=col))))
        else:
            rows.append((f"(unlock you key1 door1) where (iscolor door1 {col})",
                         request(rng.choice(OPEN_WITH_KEY).format(c=col))))


# Purpose modifiers: "a key for/to <door>" asks for the key, not for the door to
# be opened (no opening verb). Drawn from their own generator so that adding them
# leaves every other generated row unchanged.
prng = random.Random(20240611)
PURPOSE_DOOR = ["the {c} door", "that {c} door", "this {c} door", "the {c} door over there",
                "the locked {c} door", "the {c} door ahead"]
PURPOSE_HANDOVER = ["bring me the key to {d}", "hand me a key for {d}", "pass me the key to {d}",
                    "give me the {c} key for {d0}", "fetch me a key for {d}", "toss me the key for {d}",
                    "bring me the {c} one for {d0}", "find me the key to {d}"]
PURPOSE_HANDOVER_STATEMENTS = ["I need the key to {d}.", "I'd like a key for {d}.", "Can I have the key to {d}?",
                               "I'm missing a key for {d}.", "The key for {d}, please.",
                               "I want a key for {d}, can you bring it?", "Could I get the key to {d}?"]
PURPOSE_PICKUP = ["pick up the key to {d}", "grab a key for {d}", "go find the key to {d}",
                  "collect the {c} key for {d0}", "look for a key for {d}", "pick up the {c} one for {d0}",
                  "go get the {c} key for {d0}", "fetch the key for {d}",
                  "search for the key to {d}"]
PURPOSE_FRAMES = ["Can you {vp}?", "Could you {vp}?", "Please {vp}.", "{VP}.", "Would you {vp}?",
                  "{VP}, please.", "I need you to {vp}.", "Hey, could you {vp}?"]
PURPOSE_PLAIN_DOOR = ["that door", "this door", "the door", "the door over there", "the locked door"]


def dkg_purpose(rows, count):
    for _ in range(count):
        col = prng.choice(COLOURS)
        coloured = prng.random() < 0.8
        d = prng.choice(PURPOSE_DOOR).format(c=col) if coloured else prng.choice(PURPOSE_PLAIN_DOOR)
        d0 = prng.choice(PURPOSE_PLAIN_DOOR)
        r = prng.random()
        if r < 0.25:
            utt = prng.choice(PURPOSE_HANDOVER_STATEMENTS).format(d=d)
            utt = utt[0].upper() + utt[1:]
            action = "handover"
        else:
            action = "handover" if r < 0.6 else "pickup"
            tmpl = prng.choice(PURPOSE_HANDOVER if action == "handover" else PURPOSE_PICKUP)
            if "{c}" in tmpl:
                coloured = True
            vp = tmpl.format(c=col, d=d, d0=d0)
            frame = prng.choice(PURPOSE_FRAMES)
            utt = frame.replace("{vp}", vp).replace("{VP}", cap(vp))
        cmd = f"({action} you me key1)" if action == "handover" else "(pickup you key1)"
        if coloured:
            cmd += f" where (iscolor key1 {col})"
        rows.append((cmd, utt))


def build_dkg():
    rows = []
    dkg_single(rows, 300)
    dkg_same_colour_group(rows, 110, 2)
    dkg_same_colour_group(rows, 40, 3)
    dkg_two_colours(rows, 80)
    dkg_mixed(rows, 110)
    dkg_chain(rows, 15)
    dkg_key_for_door(rows, 45)
    joint(rows, 120)
    rows.extend(DKG_FREE)
    dkg_purpose(rows, 60)
    return rows


# --------------------------------------------------------------------------- VirtualHome
# type -> (singular phrases, plural phrases, category words)
VH_TYPES = {
    "plate": (["plate", "dinner plate", "dish", "plate"], ["plates", "dinner plates", "dishes", "plates"]),
    "bowl": (["bowl", "bowl", "soup bowl"], ["bowls", "bowls", "soup bowls"]),
    "cutleryfork": (["fork", "fork", "dinner fork"], ["forks", "forks", "dinner forks"]),
    "cutleryknife": (["knife", "knife", "butter knife", "table knife"], ["knives", "knives", "butter knives"]),
    "wine": (["wine", "bottle of wine", "wine bottle"], ["bottles of wine", "wine bottles"]),
    "juice": (["juice", "bottle of juice", "juice"], ["bottles of juice", "juices"]),
    "cupcake": (["cupcake", "cupcake", "little cake"], ["cupcakes", "cupcakes", "cakes"]),
    "cheese": (["cheese", "block of cheese", "cheese"], ["blocks of cheese", "cheeses"]),
    "waterglass": (["glass", "water glass", "drinking glass", "cup", "glass"],
                   ["glasses", "water glasses", "drinking glasses", "cups", "glasses"]),
    "wineglass": (["wine glass", "wineglass", "wine glass"], ["wine glasses", "wineglasses", "wine glasses"]),
    "onion": (["onion"], ["onions"]),
    "tomato": (["tomato"], ["tomatoes"]),
    "potato": (["potato"], ["potatoes"]),
    "carrot": (["carrot"], ["carrots"]),
    "chicken": (["chicken", "chicken", "piece of chicken"], ["pieces of chicken", "chickens"]),
    "salmon": (["salmon", "fish", "salmon fillet", "salmon"], ["salmon fillets", "fish", "pieces of salmon"]),
    "cucumber": (["cucumber"], ["cucumbers"]),
    "chefknife": (["chef's knife", "chef knife", "kitchen knife", "big knife", "cooking knife"],
                  ["chef's knives", "kitchen knives", "chef knives"]),
    "cuttingboard": (["cutting board", "chopping board", "board", "cutting board"],
                     ["cutting boards", "chopping boards", "boards"]),
}
MASS = {"wine", "juice", "cheese", "chicken", "salmon"}
CATEGORY = {
    frozenset(["carrot", "onion"]): ["veggies", "vegetables"],
    frozenset(["tomato", "cucumber"]): ["veggies", "salad vegetables", "vegetables"],
    frozenset(["potato", "carrot"]): ["vegetables", "veggies"],
    frozenset(["onion", "potato"]): ["vegetables", "veggies"],
    frozenset(["cutleryfork", "cutleryknife"]): ["cutlery", "silverware", "utensils"],
    frozenset(["plate", "bowl"]): ["dishes", "dishware"],
    frozenset(["wine", "juice"]): ["drinks", "something to drink"],
    frozenset(["waterglass", "wineglass"]): ["glasses", "glassware"],
    frozenset(["chefknife", "cuttingboard"]): ["knife and board", "prep tools"],
    frozenset(["chicken", "salmon"]): ["meat and fish", "proteins"],
}
NUM = {2: "two", 3: "three", 4: "four"}


def vh_np(t, n):
    sg, pl = VH_TYPES[t]
    if n == 1:
        w = rng.choice(sg)
        if t in MASS and w == t:
            return rng.choice([f"some {w}", f"the {w}", f"{w}"])
        art = "an" if w[0] in "aeiou" else "a"
        return rng.choice([f"{art} {w}", f"the {w}", f"{art} {w}", f"one {w}"])
    w = rng.choice(pl)
    if t in MASS and w == t:
        return f"{NUM[n]} servings of {w}"
    return rng.choice([f"{NUM[n]} {w}", f"{NUM[n]} {w}", f"the {w}", f"some {w}", f"both {w}" if n == 2 else f"all the {w}",
                       f"a couple of {w}" if n == 2 else f"a few {w}"])


def vh_list(nps):
    if len(nps) == 1:
        return nps[0]
    if len(nps) == 2:
        return f"{nps[0]} and {nps[1]}"
    return ", ".join(nps[:-1]) + rng.choice([", and ", " and "]) + nps[-1]


VH_VERBS = ["get {np}", "grab {np}", "bring {np}", "bring me {np}", "get me {np}", "fetch {np}",
            "go get {np}", "find {np}", "hand me {np}", "pass me {np}", "give me {np}", "pick up {np}",
            "bring {np} to the table", "put {np} on the table", "set out {np}", "go find {np}",
            "grab me {np}", "bring over {np}", "fetch me {np}", "collect {np}", "take out {np}",
            "set {np} on the table", "lay out {np}", "go and grab {np}"]
VH_STATEMENTS = ["We need {np}.", "I need {np}.", "We still need {np}.", "We'll need {np}.",
                 "Let's get {np}.", "The table needs {np}.", "I want {np}.", "Missing {np}.",
                 "Still missing {np}.", "{NP}, please.", "We're short {np}.", "Can I have {np}?",
                 "Could we get {np}?", "I'd like {np}."]


def vh_sentence(np):
    if rng.random() < 0.3:
        s = rng.choice(VH_STATEMENTS)
        return s.replace("{NP}", cap(np)).replace("{np}", np)
    return request(rng.choice(VH_VERBS).format(np=np))


def vh_command(groups):
    """groups: list of (type, count) in order."""
    acts = []
    for t, n in groups:
        for k in range(1, n + 1):
            acts.append(f"(grab you {t}{k})")
    return " ".join(acts)


def build_vh():
    rows = []
    types = list(VH_TYPES)
    for _ in range(170):  # one item
        t = rng.choice(types)
        rows.append((vh_command([(t, 1)]), vh_sentence(vh_np(t, 1))))
    for _ in range(110):  # several of one type
        t = rng.choice(types)
        n = rng.choice([2, 2, 2, 3, 3, 4])
        rows.append((vh_command([(t, n)]), vh_sentence(vh_np(t, n))))
    for _ in range(170):  # two types (counts up to 2+2 / 3+1)
        a, b = rng.sample(types, 2)
        na, nb = rng.choice([(1, 1), (1, 1), (1, 1), (2, 1), (1, 2), (2, 2), (3, 1)])
        cmd = vh_command([(a, na), (b, nb)])
        key = frozenset([a, b])
        if key in CATEGORY and na == 1 and nb == 1 and rng.random() < 0.45:
            np = rng.choice(["the ", "some ", ""]) + rng.choice(CATEGORY[key])
        else:
            np = vh_list([vh_np(a, na), vh_np(b, nb)])
        rows.append((cmd, vh_sentence(np)))
    cats = sorted(CATEGORY.items(), key=lambda kv: sorted(kv[0]))
    for _ in range(45):  # category words for two related types
        key, words = rng.choice(cats)
        a, b = sorted(key)
        np = rng.choice(["the ", "some ", ""]) + rng.choice(words)
        rows.append((vh_command([(a, 1), (b, 1)] if rng.random() < 0.5 else [(b, 1), (a, 1)]), vh_sentence(np)))
    for _ in range(60):  # three or four items: one type, or two types (enumeration rule)
        a, b = rng.sample(types, 2)
        shape = rng.choice([[(a, 2), (b, 1)], [(a, 1), (b, 2)], [(a, 3)], [(a, 2), (b, 2)], [(a, 3), (b, 1)]])
        cmd = vh_command(shape)
        rows.append((cmd, vh_sentence(vh_list([vh_np(t, n) for t, n in shape]))))
    for _ in range(40):  # three or four different types (few-shot style; not enumerated, but useful)
        k = rng.choice([3, 3, 4])
        ts = rng.sample(types, k)
        rows.append((vh_command([(t, 1) for t in ts]), vh_sentence(vh_list([vh_np(t, 1) for t in ts]))))
    rows.extend([
        ("(grab you plate1) (grab you cutleryfork1) (grab you cutleryknife1)", "Could you set a place at the table?"),
        ("(grab you wine1) (grab you wineglass1)", "Pour me a glass of wine?"),
        ("(grab you juice1) (grab you waterglass1)", "I'd like some juice in a glass."),
        ("(grab you cuttingboard1) (grab you chefknife1)", "I need something to chop on and a knife."),
        ("(grab you onion1) (grab you carrot1) (grab you potato1)", "Bring me the vegetables for the stew."),
        ("(grab you tomato1) (grab you cucumber1)", "Get the stuff for a salad."),
        ("(grab you salmon1)", "Grab the fish from the fridge."),
        ("(grab you chicken1)", "Take the chicken out, please."),
        ("(grab you cupcake1) (grab you cupcake2)", "Dessert for two, please: cupcakes."),
        ("(grab you cheese1)", "Some cheese would be nice."),
        ("(grab you plate1) (grab you plate2) (grab you plate3) (grab you plate4)", "Set out four plates."),
        ("(grab you bowl1) (grab you bowl2) (grab you bowl3)", "We need three bowls for soup."),
        ("(grab you cutleryfork1) (grab you cutleryfork2)", "Forks for both of us, please."),
        ("(grab you waterglass1) (grab you waterglass2)", "Two glasses of water, please."),
        ("(grab you wineglass1) (grab you wineglass2)", "Could you get a pair of wine glasses?"),
    ])
    return rows


def write(path, rows, header):
    with open(path, "w") as f:
        f.write(header)
        for cmd, utt in rows:
            assert "\t" not in cmd and "\t" not in utt
            f.write(f"{cmd}\t{utt}\n")


HEADER = ("# command<TAB>utterance pairs for the embedded language model.\n"
          "# Generated by make_corpus.py from hand-written phrasings; do not edit by hand.\n")

if __name__ == "__main__":
    write(os.path.join(HERE, "corpus-dkg.tsv"), build_dkg(), HEADER)
    write(os.path.join(HERE, "corpus-vh.tsv"), build_vh(), HEADER)
