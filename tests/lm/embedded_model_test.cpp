#include "lm/embedded_model_test.hpp"

namespace clips::lm {
namespace embedded_model_test {
TEST(EmbeddedTokens, LowerCasesExpandsContractionsAndKeepsPunctuation) {
  EXPECT_EQ(tokenize_utterance(" I'll get the Red key, can't you?\n"),
            (std::vector<std::string>{"i", "will", "get", "the", "red", "key", ",", "can", "not", "you", "?"}));
  EXPECT_EQ(tokenize_utterance("I'm here; won't go."),
            (std::vector<std::string>{"i", "am", "here", ",", "will", "not", "go", "."}));
}

TEST(EmbeddedTokens, ChatSpellingsAreReadAsTheirWords) {
  EXPECT_EQ(tokenize_utterance("can u gimme dis key pls"),
            (std::vector<std::string>{"can", "you", "give", "me", "this", "key", "please"}));
  EXPECT_EQ(tokenize_utterance("im gonna get em, dont worry"),
            (std::vector<std::string>{"i", "am", "going", "to", "get", "them", ",", "do", "not", "worry"}));
  // Words that merely contain a chat spelling are left alone.
  EXPECT_EQ(tokenize_utterance("use the umbrella"), (std::vector<std::string>{"use", "the", "umbrella"}));
  // So the chat form scores like the spelled-out one.
  const std::string p = pragmatic_prompt("(handover you me key1) where (iscolor key1 yellow)");
  EXPECT_DOUBLE_EQ(score(p, "can u pass me dis yellow key pls"), score(p, "can you pass me this yellow key please"));
}

// Tokens neither the model nor WordNet knows are read as the content word one
// edit away; elongations as their word; real words are never "corrected".
TEST(EmbeddedTokens, MisspellingsAreReadAsTheWordsTheyMisspell) {
  auto m = model().model_for_prompt(pragmatic_prompt("(pickup you key1)"));
  auto words = [&](const char* text) { return m->encode(text).words; };
  EXPECT_EQ(words("i neeed the yelow kye pleeease"),
            (std::vector<std::string>{"i", "need", "the", "yellow", "key", "please"}));
  EXPECT_EQ(words("can you unlok the rd dooor"),
            (std::vector<std::string>{"can", "you", "unlock", "the", "red", "door"}));
  // Real words, function words and tokens with digits stay as written.
  EXPECT_EQ(words("soon the kid has 2 keyz9"), (std::vector<std::string>{"soon", "the", "kid", "has", "2", "keyz9"}));
  // So a slip scores like the word, and its colour still tells the keys apart.
  const std::string yellow = pragmatic_prompt("(handover you me key1) where (iscolor key1 yellow)");
  const std::string red = pragmatic_prompt("(handover you me key1) where (iscolor key1 red)");
  EXPECT_DOUBLE_EQ(score(yellow, "can you pass me the yelow kye?"), score(yellow, "can you pass me the yellow key?"));
  EXPECT_GT(score(yellow, "can you pass me the yelow kye?"), score(red, "can you pass me the yelow kye?") + 2.0);
}

TEST(EmbeddedPrompt, SplitsFewShotBlockAndQuery) {
  const std::string p = literal_prompt("(pickup you key1) where (iscolor key1 red)");
  auto [block, command] = split_prompt(p);
  EXPECT_EQ(command, "(pickup you key1) where (iscolor key1 red)");
  auto examples = parse_fewshot_block(block);
  ASSERT_EQ(examples.size(), 12u);
  EXPECT_EQ(examples[0].second, "Help me unlock the green and yellow doors.");
  EXPECT_EQ(split_prompt("\n"), (std::pair<std::string, std::string>{"", ""}));
  EXPECT_THROW(split_prompt("Input: (pickup you key1)\nOutput: x"), LmError);
}

TEST(EmbeddedNormalisation, NextTokenDistributionSumsToOne) {
  auto m = model().model_for_prompt(literal_prompt("(pickup you key1)"));
  for (const char* cmd : {"(handover you me key1) where (iscolor key1 red)",
                          "(unlock you key1 door1) (pickup me key2) where (iscolor door1 green) (iscolor key2 blue)",
                          "(pickup you key1) (pickup you key2) where (iscolor key1 red) (iscolor key2 red)",
                          "(grab you plate1) (grab you mug1)", "(frobnicate you widget1) where (iscolor widget1 mauve)",
                          ""}) {
    for (bool request : {true, false}) {
      EXPECT_NEAR(m->next_token_mass(cmd, true, request), 1.0, 1e-9) << cmd;
      EXPECT_NEAR(m->next_token_mass(cmd, false, request), 1.0, 1e-9) << cmd;
    }
  }
}

TEST(EmbeddedNormalisation, LengthDistributionIsProperAndEndCarriesMass) {
  auto m = model().model_for_prompt(pragmatic_prompt("(pickup you key1)"));
  for (int a = 0; a <= 5; ++a) {
    const double mass = m->length_mass(a, 5000);
    EXPECT_NEAR(mass, 1.0, 1e-6) << a;
    EXPECT_LE(mass, 1.0 + 1e-9);
  }
  // The end event carries probability: a complete utterance is less likely than its prefix.
  const std::string p = literal_prompt("(pickup you key1) where (iscolor key1 red)");
  const double full = model().score({{p, " Pick up the red key.\n"}})[0];
  const double prefix = model().score({{p, " Pick up the red key."}})[0];
  EXPECT_LT(full, prefix);
  EXPECT_LT(prefix, 0.0);
}

// Beyond the lengths the corpus holds many of, the length model is smooth and
// about the same for every command size: one long training utterance used to
// make its exact length up to 5 nats likelier than its neighbours, and the
// buckets' tails differed by the log ratio of their training counts.
TEST(EmbeddedNormalisation, LengthTailIsSmoothAndSharedByCommandSizes) {
  auto m = model().model_for_prompt(pragmatic_prompt("(pickup you key1)"));
  auto log_p = [&](int a, int n) { return std::log(m->length_mass(a, n) - m->length_mass(a, n - 1)); };
  double worst_step = 0;
  for (int a = 1; a <= 4; ++a)
    for (int n = 12; n < 60; ++n) worst_step = std::max(worst_step, std::fabs(log_p(a, n + 1) - log_p(a, n)));
  std::printf("[length] largest step between neighbouring lengths 12..60: %.2f nats\n", worst_step);
  EXPECT_LT(worst_step, 1.5);
  for (int n : {35, 50, 80})
    for (int a = 2; a <= 4; ++a) EXPECT_NEAR(log_p(a, n), log_p(1, n), 0.5) << a << " actions, length " << n;
}

// A request padded with a reason ("since it's right next to me") is long; the
// joint command that names both keys must still beat the one that drops the
// speaker's own key. With the old length model it lost by 3.9 nats.
TEST(EmbeddedModel, PaddedJointInstructionsKeepTheSpeakersPart) {
  const std::string joint = pragmatic_prompt(
      "(pickup me ?key1) (pickup you ?key2) where (iscolor ?key1 red) (iscolor ?key2 yellow)");
  const std::string yours = pragmatic_prompt("(pickup you ?key1) where (iscolor ?key1 yellow)");
  for (const char* u : {"I'll take this red key myself since it's right next to me. Could you go and find a yellow one?",
                        "I will pick up this red key. Can you find a yellow one?"}) {
    std::printf("[padded joint] %.2f nats: %s\n", score(joint, u) - score(yours, u), u);
    EXPECT_GT(score(joint, u), score(yours, u)) << u;
  }
}

TEST(EmbeddedNormalisation, FiniteSetOfUtterancesSumsBelowOne) {
  const std::string p = literal_prompt("(handover you me key1) where (iscolor key1 red)");
  double total = 0;
  for (const char* u : {"Pass me the red key.", "Give me the red key.", "Red key please.", "Hand me that key.",
                        "Bring me the red key!", "The red key.", "Key.", "Could you pass me the red key?",
                        "zzz qqq", "red red red red red red red red"}) {
    total += std::exp(score(p, u));
  }
  EXPECT_GT(total, 0.0);
  EXPECT_LE(total, 1.0);
}

TEST(EmbeddedNormalisation, UnknownWordsHaveNonZeroProbability) {
  const std::string p = vh_prompt("(grab you plate1)");
  const double s = score(p, "Xylophone quibbles plate zqxj?");
  EXPECT_TRUE(std::isfinite(s));
  EXPECT_LT(s, score(p, "Can you get a plate?"));
}

TEST(EmbeddedNormalisation, VeryLongUnknownWordsStayFiniteAndKeepTheComparison) {
  // The character model gives a word of a few hundred letters a probability
  // below the double range; the score must stay a finite log-probability,
  // fall with the length, and leave the comparison between commands as it is
  // for a short unknown word (the word's factor is the same under both).
  const std::string red = literal_prompt("(handover you me key1) where (iscolor key1 red)");
  const std::string blue = literal_prompt("(unlock you key1 door1) where (iscolor door1 blue)");
  auto utterance = [](size_t letters) { return "Can you pass me the " + std::string(letters, 'x') + " key?"; };
  double last = 0;
  for (size_t letters : {20, 150, 300, 3000}) {
    const double r = score(red, utterance(letters)), b = score(blue, utterance(letters));
    ASSERT_TRUE(std::isfinite(r) && std::isfinite(b)) << letters;
    if (letters > 20) {
      EXPECT_LT(r, last) << letters;
    }
    EXPECT_NEAR(r - b, score(red, utterance(20)) - score(blue, utterance(20)), 1e-6) << letters;
    last = r;
  }
  EXPECT_TRUE(std::isfinite(score("\n", utterance(3000))));
}

TEST(EmbeddedNormalisation, SeveralLongUnknownWordsInOneClauseStayFinite) {
  // Each word alone is above the rescaling threshold, but their product in
  // one clause used to underflow (score -inf, prefix score NaN; found by
  // fuzz/utterance_fuzz).
  const std::string red = literal_prompt("(handover you me key1) where (iscolor key1 red)");
  const std::string u = "the h" + std::string(60, 'c') + "e and the i" + std::string(80, 'c') + "n";
  EXPECT_TRUE(std::isfinite(score(red, u)));
  std::vector<clips::lm::ScoreRequest> prefix = {{red, " " + u}};
  EXPECT_TRUE(std::isfinite(model().score(prefix)[0]));
}

TEST(EmbeddedModel, IsDeterministicAcrossInstancesAndCalls) {
  const std::string p = pragmatic_prompt("(unlock you key1 door1) where (iscolor door1 blue)");
  const double a = score(p, "Can you open the blue door?");
  const double b = score(p, "Can you open the blue door?");
  EmbeddedLanguageModel other;
  const double c = other.score({{p, " Can you open the blue door?\n"}})[0];
  EXPECT_EQ(a, b);
  EXPECT_EQ(a, c);
}

TEST(EmbeddedModel, ConcurrentScoringMatchesSequential) {
  EmbeddedLanguageModel m;
  std::vector<ScoreRequest> batch;
  for (const char* c : {"(pickup you key1) where (iscolor key1 red)", "(grab you mug1)",
                        "(handover you me key1) (handover you me key2) where (iscolor key1 red) (iscolor key2 red)"}) {
    batch.push_back({literal_prompt(c), " Bring me both red keys, please.\n"});
    batch.push_back({vh_prompt(c), " A mug, please.\n"});
  }
  std::vector<std::vector<double>> results(4);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < results.size(); ++t) {
    threads.emplace_back([&, t] { results[t] = m.score(batch); });
  }
  for (auto& th : threads) th.join();
  const auto sequential = model().score(batch);
  for (const auto& r : results) EXPECT_EQ(r, sequential);
}

TEST(EmbeddedModel, TrainsOncePerFewShotBlock) {
  EmbeddedLanguageModel m;
  m.score({{literal_prompt("(pickup you key1)"), " Get it.\n"},
           {literal_prompt("(handover you me key1)"), " Give it.\n"}});
  EXPECT_EQ(m.trained_blocks(), 1u);
  m.score({{pragmatic_prompt("(pickup you key1)"), " Get it.\n"}, {"\n", " Hello.\n"}});
  EXPECT_EQ(m.trained_blocks(), 3u);
}

TEST(EmbeddedModel, EmptyCommandPromptScoresEverythingAlike) {
  // The "\n" prompt of a hypothesis without commands scores utterances, but
  // worse than a matching command and without preferring any command.
  const double none = score("\n", "Can you open the blue door?");
  EXPECT_TRUE(std::isfinite(none));
  EXPECT_LT(none, score(literal_prompt("(unlock you key1 door1) where (iscolor door1 blue)"),
                        "Can you open the blue door?"));
}

TEST(EmbeddedModel, NumberWordsFavourMultiActionCommands) {
  const std::string one = literal_prompt("(pickup you key1) where (iscolor key1 green)");
  const std::string two =
      literal_prompt("(pickup you key1) (pickup you key2) where (iscolor key1 green) (iscolor key2 green)");
  EXPECT_GT(score(two, "Grab both green keys."), score(one, "Grab both green keys."));
  EXPECT_GT(score(one, "Grab the green key."), score(two, "Grab the green key."));
  const std::string p1 = vh_prompt("(grab you plate1)");
  const std::string p2 = vh_prompt("(grab you plate1) (grab you plate2)");
  EXPECT_GT(score(p2, "Get two plates."), score(p1, "Get two plates."));
  EXPECT_GT(score(p1, "Get a plate."), score(p2, "Get a plate."));
}

TEST(EmbeddedModel, NumberWordsBindToTheirNoun) {
  // In "two forks" the number counts forks: a pair of wine glasses in the
  // command cannot use it to count as mentioned, so that group pays the full
  // odds of silence (log(0.95 / 0.05) = 2.9 nats at the clamp). Unbound, "two"
  // let it speak and the gap was 2.2.
  const std::string forks = vh_prompt("(grab you cutleryfork1) (grab you cutleryfork2)");
  const std::string forks_glasses =
      vh_prompt("(grab you cutleryfork1) (grab you cutleryfork2) (grab you wineglass1) (grab you wineglass2)");
  const char* u = "Could you get two forks?";
  std::printf("[number binding] gap %.2f nats\n", score(forks, u) - score(forks_glasses, u));
  EXPECT_GT(score(forks, u), score(forks_glasses, u) + 2.6);
  // Said of both, the number serves both groups.
  const char* v = "Could you get two forks and two glasses?";
  EXPECT_GT(score(forks_glasses, v), score(forks, v) + 2.0);
}

TEST(EmbeddedModel, SpeakerClausesDoNotClaimTheListenersColour) {
  const std::string blue = pragmatic_prompt("(pickup you key1) where (iscolor key1 blue)");
  const std::string red = pragmatic_prompt("(pickup you key1) where (iscolor key1 red)");
  const char* u = "I'll grab the red key, could you pick up the blue one?";
  EXPECT_GT(score(blue, u), score(red, u));
  const char* v = "Can you get the yellow key? I'm going for the green one.";
  EXPECT_GT(score(pragmatic_prompt("(pickup you key1) where (iscolor key1 yellow)"), v),
            score(pragmatic_prompt("(pickup you key1) where (iscolor key1 green)"), v));
}

// A statement of the speaker's need names what a hand-over to the speaker
// brings: the colour is evidence as in a request. Before statements could
// talk about hand-overs, "I'm in need of the blue key" gave the blue hand-over
// 1.2 nats over the red one, "I am after the blue key" 0.8.
TEST(EmbeddedModel, StatementsOfNeedNameWhatIsHandedToTheSpeaker) {
  const std::string blue = pragmatic_prompt("(handover you me key1) where (iscolor key1 blue)");
  const std::string red = pragmatic_prompt("(handover you me key1) where (iscolor key1 red)");
  for (const char* u : {"I'm in need of the blue key.", "I am after the blue key."}) {
    std::printf("[statement of need] %.2f nats: %s\n", score(blue, u) - score(red, u), u);
    EXPECT_GT(score(blue, u), score(red, u) + 2.5) << u;
  }
}

// A situation described first and the request pointing back with "it": the
// colour names the object of the request, whatever the first clause's type.
// Read as the speaker's own statement it said little against a blue door
// (3.0 and 0.7 nats before).
TEST(EmbeddedModel, ColoursOfWhatARequestPointsBackToCount) {
  const std::string red = pragmatic_prompt("(unlock you ?key1 ?door1) where (iscolor ?door1 red)");
  const std::string blue = pragmatic_prompt("(unlock you ?key1 ?door1) where (iscolor ?door1 blue)");
  for (const char* u : {"This red door has me stuck; it'd be great if you came and took care of it.",
                        "I'm right up against this red door, could you come over here and take care of it for me?"}) {
    std::printf("[points back] %.2f nats: %s\n", score(red, u) - score(blue, u), u);
    EXPECT_GT(score(red, u), score(blue, u) + 4.0) << u;
  }
  auto m = model().model_for_prompt(red);
  const EncodedUtterance a = m->encode("This red door is locked. Could you open it?");
  EXPECT_EQ(a.asked_for, (std::vector<char>{0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
  // The empty "it" of "it would be great" and a request without a pronoun point nowhere.
  for (const char* u : {"This blue key is mine. It would be great if you found a yellow one.",
                        "I'll get the blue key, could you open the red door?"}) {
    const EncodedUtterance e = m->encode(u);
    EXPECT_EQ(std::count(e.asked_for.begin(), e.asked_for.end(), 1), 0) << u;
  }
}

// Noun fields do not learn places: the corpus's "kitchen knife" must not make
// "kitchen" name the chef's knife, or "the wine is in the kitchen" asks for a
// knife (before, the knife won by 0.3 nats; the wine now wins by 6.5).
TEST(EmbeddedModel, PlacesNameNoObject) {
  EXPECT_TRUE(WordNetLexicon::instance().names_place("kitchen"));
  EXPECT_TRUE(WordNetLexicon::instance().names_place("cupboard"));
  for (const char* w : {"plate", "knife", "key", "door", "gem", "cabinet", "table"})
    EXPECT_FALSE(WordNetLexicon::instance().names_place(w)) << w;
  const std::string wine = vh_prompt("(grab you wine1)");
  const std::string knife = vh_prompt("(grab you chefknife1)");
  const char* u = "Do you think you could get the wine for me? It should be over in the kitchen somewhere.";
  EXPECT_GT(score(wine, u), score(knife, u) + 3.0);
  // Where it is part of the object's name, the name still speaks for the knife.
  EXPECT_GT(score(knife, "Could you get the kitchen knife?"), score(wine, "Could you get the kitchen knife?") + 3.0);
}

// What a thing is for, from WordNet: the verbs derived from the tool's
// sense and their hypernyms, and the gloss's purpose verbs and adjectives.
// Only instruments and containers have uses; food has none.
TEST(EmbeddedModel, FunctionWordsSayWhatAToolIsFor) {
  auto has = [](const std::string& type, const std::string& word) {
    for (const auto& [w, p] : WordNetLexicon::instance().function_words(type))
      if (w == word) return p > 0;
    return false;
  };
  EXPECT_TRUE(has("spade", "dig"));     // spade (v) -> dig
  EXPECT_TRUE(has("knife", "sharp"));   // "... with a sharp edge"
  EXPECT_TRUE(has("knife", "cutting"));
  EXPECT_TRUE(has("thermometer", "measure"));
  EXPECT_TRUE(has("saw", "cut"));
  EXPECT_TRUE(WordNetLexicon::instance().function_words("apple").empty());
  EXPECT_TRUE(WordNetLexicon::instance().function_words("flour").empty());
}

TEST(EmbeddedModel, ColoursBindToNounsOfTheirObjectsType) {
  // "red door": the red belongs to a door. A command whose only red object is
  // a gem must not explain it by copying the gem's colour, and a command with
  // a red door must win.
  const std::string red_door = pragmatic_prompt("(unlock you key1 door1) where (iscolor door1 red)");
  const std::string red_gem =
      pragmatic_prompt("(unlock you key1 door1) (pickup me gem1) where (iscolor door1 blue) (iscolor gem1 red)");
  const std::string blue_door = pragmatic_prompt("(unlock you key1 door1) where (iscolor door1 blue)");
  const char* u = "Can you come and open this red door?";
  EXPECT_GT(score(red_door, u), score(red_gem, u) + 2.0);
  // The gem's colour buys (almost) nothing over a command with no red at all.
  EXPECT_LT(score(red_gem, u), score(blue_door, u) + 1.0);
  // ... while "the red gem" may still copy it.
  const char* v = "Can you open the blue door? I'm going for the red gem.";
  EXPECT_GT(score(red_gem, v), score(blue_door, v));
  // In "a key for this yellow door" the colour may come from the key (keys
  // open doors of their colour), not from a yellow gem.
  const std::string yellow_key = pragmatic_prompt("(pickup you key1) where (iscolor key1 yellow)");
  const std::string yellow_gem =
      pragmatic_prompt("(pickup you key1) (pickup me gem1) where (iscolor key1 blue) (iscolor gem1 yellow)");
  const char* w = "I need a key for this yellow door.";
  EXPECT_GT(score(yellow_key, w), score(yellow_gem, w));
  // The same through a purpose infinitive: "a key to open this yellow door".
  const char* w2 = "Could you get me a key to open this yellow door?";
  EXPECT_GT(score(yellow_key, w2), score(pragmatic_prompt("(pickup you key1) where (iscolor key1 blue)"), w2) + 0.5);
  // ... and through a relative clause: "the key that opens the yellow door".
  const char* w3 = "Get me the key that opens the yellow door.";
  EXPECT_GT(score(yellow_key, w3), score(pragmatic_prompt("(pickup you key1) where (iscolor key1 blue)"), w3) + 0.5);
  // ... and when the purpose comes first: "For this yellow door, I need a key."
  const char* w4 = "For this yellow door, I need a key.";
  EXPECT_GT(score(yellow_key, w4), score(pragmatic_prompt("(pickup you key1) where (iscolor key1 blue)"), w4) + 1.5);
  // A colour after its noun describes that noun: in "the key blue" the blue
  // is the key's, not a blue gem's (before, the blue gem's command won by 1.7 nats).
  const std::string blue_key_me = pragmatic_prompt("(handover you me key1) where (iscolor key1 blue)");
  const std::string blue_gem =
      pragmatic_prompt("(handover you me key1) (pickup me gem1) where (iscolor key1 red) (iscolor gem1 blue)");
  const char* y = "Please pass to me the key blue.";
  EXPECT_GT(score(blue_key_me, y), score(blue_gem, y) + 3.0);
  // A colour whose head says nothing about the type ("the yellow one") is unconstrained.
  const char* x = "Could you pick up the yellow one?";
  EXPECT_GT(score(yellow_key, x), score(pragmatic_prompt("(pickup you key1) where (iscolor key1 blue)"), x));
}

TEST(EmbeddedModel, MiscolouringTheCommandsObjectCostsMoreThanSilence) {
  // A speaker who means the blue door does not call it red: "red door" under
  // a blue-door command must cost more than under a command silent on colour.
  const std::string red_door = pragmatic_prompt("(unlock you key1 door1) where (iscolor door1 red)");
  const std::string blue_door = pragmatic_prompt("(unlock you key1 door1) where (iscolor door1 blue)");
  const std::string any_door = pragmatic_prompt("(unlock you key1 door1)");
  const char* u = "Can you unlock the red door?";
  EXPECT_GT(score(red_door, u), score(any_door, u));
  EXPECT_LT(score(blue_door, u), score(any_door, u) - 1.0);
  // Only objects in the clause's own role count: the speaker's "red key" says
  // nothing about the colour of the key the listener is asked to get ...
  const std::string yellow_key = pragmatic_prompt("(pickup you key1) where (iscolor key1 yellow)");
  const std::string red_key = pragmatic_prompt("(pickup you key1) where (iscolor key1 red)");
  const std::string any_key = pragmatic_prompt("(pickup you key1)");
  const char* j = "I'm going for the red key. Can you get the yellow key?";
  EXPECT_GT(score(yellow_key, j), score(any_key, j) + 1.0);
  // ... while "the yellow key" in the request does contradict a red one.
  EXPECT_LT(score(red_key, j), score(any_key, j));
}

// "more" appears in training mostly next to number words ("two more
// glasses"), so EM gives it to the number fields; without background mass of
// its own, "one more plate" favoured any command with a count in it over the
// single plate that was asked for (by 2.9 nats). The margin is small now
// (0.4 nats; "Bring one more plate." still leans 0.2 nats the other way):
// leaving a whole action group unmentioned stays too cheap in this model.
TEST(EmbeddedModel, WordsOwnedByAFieldDoNotFavourCommandsThatHaveIt) {
  const std::string u = "Get me one more plate.";
  EXPECT_GT(score(vh_prompt("(grab you plate1)"), u),
            score(vh_prompt("(grab you cutleryfork1) (grab you cutleryfork2) (grab you plate1)"), u));
}

TEST(EmbeddedModel, UnseenItemTypesUseWordNet) {
  // "mug" never occurs in the corpus; WordNet links "cup" and "mugs" to it.
  const std::string mug = vh_prompt("(grab you mug1)");
  const std::string plate = vh_prompt("(grab you plate1)");
  EXPECT_GT(score(mug, "Can you bring me a mug?"), score(plate, "Can you bring me a mug?"));
  EXPECT_GT(score(vh_prompt("(grab you mug1) (grab you mug2)"), "Bring the mugs."),
            score(plate, "Bring the mugs."));
}

TEST(EmbeddedModel, DataDirectoryFromOptionsAndEnvironment) {
  // $CLIPS_DATA_DIR names the data root; the corpora are in its language/.
  const std::string root = std::string(CLIPS_SOURCE_DIR) + "/data";
  const std::string dir = root + "/language";
  EmbeddedLanguageModel explicit_dir(dir);
  EXPECT_EQ(explicit_dir.data_dir(), dir);
  ::setenv("CLIPS_DATA_DIR", root.c_str(), 1);
  EmbeddedLanguageModel from_env;
  ::unsetenv("CLIPS_DATA_DIR");
  EXPECT_EQ(from_env.data_dir(), dir);
  EXPECT_EQ(explicit_dir.name(), "embedded");
}

// A corpus file is input: its errors are InputErrors (exit 3) naming file:line.
TEST(EmbeddedModel, MissingOrMalformedCorpusIsAClearError) {
  const auto tmp = std::filesystem::temp_directory_path() / "clips_lm_corpus_test";
  std::filesystem::create_directories(tmp);
  EmbeddedModelOptions o;
  o.data_dir = tmp.string();
  o.corpus_files = {"nope.tsv"};
  try {
    EmbeddedLanguageModel m(o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nope.tsv"), std::string::npos) << e.what();
  }
  {
    std::ofstream f(tmp / "bad.tsv");
    f << "# comment\n(pickup you key1)\tGet the key.\nthis line has no tab\n";
  }
  o.corpus_files = {"bad.tsv"};
  try {
    EmbeddedLanguageModel m(o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.tsv:3"), std::string::npos) << e.what();
  }
  {
    std::ofstream f(tmp / "bad2.tsv");
    f << "(pickup you key1\tGet the key.\n";
  }
  o.corpus_files = {"bad2.tsv"};
  try {
    EmbeddedLanguageModel m(o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad2.tsv:1"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(tmp);
}

TEST(EmbeddedTraining, TheModelDoesNotDependOnTheNumberOfThreads) {
  // The E-step runs on several threads and makes its additions in pair order:
  // the saved model is the same bytes on one thread and on three.
  std::ifstream in(std::string(CLIPS_SOURCE_DIR) + "/data/language/corpus-dkg.tsv");
  ASSERT_TRUE(in) << "data/language/corpus-dkg.tsv";
  std::vector<TrainingPair> pairs;
  std::string line;
  while (std::getline(in, line) && pairs.size() < 240) {
    const size_t tab = line.find('\t');
    if (line.empty() || line[0] == '#' || tab == std::string::npos) continue;
    pairs.push_back({line.substr(0, tab), line.substr(tab + 1), 1.0, "corpus-dkg.tsv"});
  }
  ASSERT_EQ(pairs.size(), 240u);
  const std::string one = AlignmentModel::train(pairs, 4, {}, 1)->save();
  const std::string three = AlignmentModel::train(pairs, 4, {}, 3)->save();
  EXPECT_GT(one.size(), 1000u);
  EXPECT_TRUE(one == three);
  // And the training moved the model: fewer iterations save other bytes.
  EXPECT_FALSE(AlignmentModel::train(pairs, 1, {}, 3)->save() == three);
}

}  // namespace embedded_model_test

}  // namespace clips::lm
