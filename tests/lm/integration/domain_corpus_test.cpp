// The corpus generated from a domain's command grammar (domain_corpus.hpp) and
// the qualifier-generic rules of the alignment model, on the workshop domain
// (data/datasets/workshop), which has no hand-written corpus and qualifies
// items by size and material instead of colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lm/alignment_model.hpp"
#include "lm/command_frame.hpp"
#include "lm/domain_corpus.hpp"
#include "lm/embedded_model.hpp"
#include "lm/wordnet_lexicon.hpp"
#include "pddl/parser.hpp"

namespace clips::lm {
namespace {

const std::string kWorkshop = std::string(CLIPS_SOURCE_DIR) + "/data/datasets/workshop";

// The workshop domain and one of its problems, read by the project's PDDL
// parser and handed over as plain strings, as a domain pack would.
DomainDescription workshop(int problem) {
  const pddl::Domain d = pddl::load_domain(kWorkshop + "/domain.pddl");
  const pddl::Problem p = pddl::load_problem(d, kWorkshop + "/problems/" + std::to_string(problem) + ".pddl", false);
  DomainDescription out;
  for (const pddl::ActionSchema& a : d.actions) {
    DomainActionSchema s{a.name, {}};
    for (pddl::TypeId t : a.param_types) s.parameter_types.push_back(d.types[static_cast<size_t>(t)].name);
    out.actions.push_back(s);
  }
  for (const pddl::TypeDef& t : d.types)
    if (t.parent >= 0) out.parent_type[t.name] = d.types[static_cast<size_t>(t.parent)].name;
  for (const pddl::ObjectDef& o : p.objects) out.objects.push_back({o.name, d.types[static_cast<size_t>(o.type)].name});
  for (const pddl::InitAtom& a : p.init_atoms) {
    const std::string& pred = d.predicates[static_cast<size_t>(a.pred)].name;
    if ((pred == "issize" || pred == "ismaterial") && a.args.size() == 2)
      out.qualifiers.push_back({pred, p.objects[static_cast<size_t>(a.args[0])].name,
                                p.objects[static_cast<size_t>(a.args[1])].name});
  }
  out.command_actions = {{"pickup", 1, 2}, {"handover", 1, 3}, {"putdown", 1, 2}};
  return out;
}

std::shared_ptr<AlignmentModel> model_for(int problem) {
  static std::map<int, std::shared_ptr<AlignmentModel>> models;
  auto& m = models[problem];
  if (!m) m = train_domain_model(workshop(problem), {});
  return m;
}

double score(const AlignmentModel& m, const std::string& command, const std::string& utterance) {
  return m.log_prob(*m.bind(command), m.encode(utterance), true);
}

// The command that scores best for an utterance, printing every score.
std::string best_of(const AlignmentModel& m, const std::string& utterance, const std::vector<std::string>& commands) {
  std::string best;
  double top = -INFINITY;
  for (const std::string& c : commands) {
    const double s = score(m, c, utterance);
    std::printf("  %8.3f  %s\n", s, c.c_str());
    if (s > top) {
      top = s;
      best = c;
    }
  }
  return best;
}

bool has_command(const std::vector<TrainingPair>& pairs, const std::string& command) {
  return std::any_of(pairs.begin(), pairs.end(), [&](const TrainingPair& p) { return p.command == command; });
}

TEST(DomainCorpus, GeneratesParsablePairsForTheWorkshop) {
  const std::vector<TrainingPair> pairs = generate_domain_corpus(workshop(1));
  std::printf("[workshop 1] %zu generated pairs; e.g. %s <-> %s\n", pairs.size(), pairs.front().command.c_str(),
              pairs.front().utterance.c_str());
  ASSERT_GT(pairs.size(), 200u);
  if (std::getenv("CLIPS_CORPUS_PRINT") != nullptr)
    for (const TrainingPair& p : pairs) std::printf("%s\t%s\n", p.command.c_str(), p.utterance.c_str());
  for (const TrainingPair& p : pairs) {
    EXPECT_NO_THROW(parse_command_frame(p.command, p.origin)) << p.command;
    EXPECT_FALSE(p.utterance.empty());
  }
  // Printed like the few-shot examples: pronouns, the focal variable, the
  // recipient, no station; every stated qualifier of the focal object.
  EXPECT_TRUE(has_command(pairs, "(handover you me plank1) where (issize plank1 big) (ismaterial plank1 wooden)"));
  EXPECT_TRUE(has_command(pairs, "(handover you me plank1) where (issize plank1 big)"));
  EXPECT_TRUE(has_command(pairs, "(pickup you hammer1) where (ismaterial hammer1 metal)"));
  EXPECT_TRUE(has_command(pairs, "(putdown you leg1)"));
  // Two-action and joint commands (the speaker's own part as "me").
  const bool joint = std::any_of(pairs.begin(), pairs.end(), [](const TrainingPair& p) {
    return p.command.rfind("(pickup me ", 0) == 0 || p.command.rfind("(putdown me ", 0) == 0;
  });
  EXPECT_TRUE(joint);
  // Qualifier values are said as adjectives, and "one" stands in for a noun.
  const auto says = [&](const std::string& text) {
    return std::any_of(pairs.begin(), pairs.end(),
                       [&](const TrainingPair& p) { return p.utterance.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(says("big plank"));
  EXPECT_TRUE(says("metal one") || says("small one") || says("big one") || says("wooden one"));
  // Deterministic.
  const std::vector<TrainingPair> again = generate_domain_corpus(workshop(1));
  ASSERT_EQ(again.size(), pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) {
    EXPECT_EQ(again[i].command, pairs[i].command);
    EXPECT_EQ(again[i].utterance, pairs[i].utterance);
  }
}

TEST(DomainCorpus, NamesBecomeWordsThroughWordNet) {
  WordNetLexicon& wn = WordNetLexicon::instance();
  const auto contains = [](const std::vector<std::string>& v, const std::string& w) {
    return std::find(v.begin(), v.end(), w) != v.end();
  };
  const std::vector<std::string> pick = wn.verb_phrases("pickup");
  EXPECT_EQ(pick.front(), "pick up");
  EXPECT_TRUE(contains(pick, "grab"));
  EXPECT_TRUE(contains(pick, "get"));
  const std::vector<std::string> hand = wn.verb_phrases("handover");
  EXPECT_EQ(hand.front(), "hand over");
  EXPECT_TRUE(contains(hand, "give"));
  EXPECT_TRUE(contains(hand, "pass"));
  EXPECT_TRUE(contains(wn.noun_phrases("plank"), "board"));
  EXPECT_EQ(wn.plural("plank"), "planks");
  // The words naming a qualifier's kind, for the attribute field's residual.
  // For colours they are the four words the model always had, in that order.
  EXPECT_EQ(wn.qualifier_words("iscolor"), (std::vector<std::string>{"colored", "coloured", "color", "colour"}));
  EXPECT_TRUE(contains(wn.qualifier_words("issize"), "size"));
  EXPECT_TRUE(contains(wn.qualifier_words("ismaterial"), "material"));
}

TEST(DomainCorpus, ModelFromTheGeneratedCorpusFindsTheBigPlank) {
  const AlignmentModel& m = *model_for(1);
  const std::string want = "(handover you me plank1) where (issize plank1 big)";
  std::printf("[could you bring me the big plank]\n");
  EXPECT_EQ(best_of(m, "could you bring me the big plank",
                    {want, "(handover you me plank1) where (issize plank1 small)",
                     "(handover you me hammer1) where (issize hammer1 big)",
                     "(handover you me leg1) where (issize leg1 small)",
                     "(handover you me screwdriver1) where (issize screwdriver1 small)",
                     "(handover you me bracket1) where (ismaterial bracket1 metal)",
                     "(handover you me plank1) where (ismaterial plank1 wooden)",
                     "(pickup you hammer1) where (issize hammer1 big)"}),
            want);
  // The size tells the two planks apart by a clear margin.
  EXPECT_GT(score(m, want, "could you bring me the big plank") -
                score(m, "(handover you me plank1) where (issize plank1 small)", "could you bring me the big plank"),
            3.0);
}

TEST(DomainCorpus, ModelFromTheGeneratedCorpusGrabsTheMetalSaw) {
  const AlignmentModel& m = *model_for(3);
  const std::string want = "(pickup you saw1) where (ismaterial saw1 metal)";
  std::printf("[grab the metal saw]\n");
  EXPECT_EQ(best_of(m, "grab the metal saw",
                    {want, "(pickup you plank1) where (ismaterial plank1 wooden)",
                     "(pickup you saw1) where (issize saw1 big)",
                     "(pickup you dowel1) where (ismaterial dowel1 wooden)",
                     "(putdown you saw1) where (ismaterial saw1 metal)",
                     "(pickup you plank1) where (issize plank1 big)"}),
            want);
  // "grab" is a pickup word, "bring me" a hand-over one.
  EXPECT_GT(score(m, want, "grab the metal saw"),
            score(m, "(handover you me saw1) where (ismaterial saw1 metal)", "grab the metal saw"));
  EXPECT_GT(score(m, "(handover you me saw1) where (ismaterial saw1 metal)", "bring me the metal saw"),
            score(m, want, "bring me the metal saw"));
}

// The workshop says "big", "small", "metal" and "wooden"; people also say
// "large", "tiny", "metallic" and "wood". WordNet's adjective senses and the
// values' derivational neighbours read those as the domain's values, so they
// score exactly like the value and tell the objects apart as it does.
TEST(DomainCorpus, QualifierSynonymsReadAsTheDomainsValues) {
  const AlignmentModel& m = *model_for(1);
  auto words = [&](const char* text) { return m.encode(text).words; };
  EXPECT_EQ(words("bring the large plank and the tiny leg"),
            (std::vector<std::string>{"bring", "the", "big", "plank", "and", "the", "small", "leg"}));
  EXPECT_EQ(words("the metallic bracket , the wood one"),
            (std::vector<std::string>{"the", "metal", "bracket", ",", "the", "wooden", "one"}));
  // Words WordNet does not relate to a value, and words of the vocabulary, stay.
  EXPECT_EQ(words("the fast plank"), (std::vector<std::string>{"the", "fast", "plank"}));
  const std::string big = "(handover you me plank1) where (issize plank1 big)";
  const std::string small = "(handover you me plank1) where (issize plank1 small)";
  EXPECT_DOUBLE_EQ(score(m, big, "could you bring me the large plank"),
                   score(m, big, "could you bring me the big plank"));
  EXPECT_GT(score(m, big, "could you bring me the huge plank"),
            score(m, small, "could you bring me the huge plank") + 3.0);
  EXPECT_GT(score(m, small, "pass me the little one"), score(m, big, "pass me the little one") + 1.0);
}

// A goal's name is a bag of words about it ("(named goal1 large)"), not a
// qualifier: a name word that WordNet relates to a value ("large", of the
// items' size "big") still reads as that value, so the sizes of the items
// stay told apart by it, and the value's other relatives follow it.
TEST(DomainCorpus, GoalNameWordsStillReadAsTheItemsValues) {
  DomainDescription d = workshop(1);
  d.goal_names = {"large-frame", "small-stool-repair"};
  const std::shared_ptr<AlignmentModel> m = train_domain_model(d, {});
  EXPECT_EQ(m->encode("bring the large plank and the huge leg").words,
            (std::vector<std::string>{"bring", "the", "big", "plank", "and", "the", "big", "leg"}));
  const std::string big = "(handover you me plank1) where (issize plank1 big)";
  const std::string small = "(handover you me plank1) where (issize plank1 small)";
  EXPECT_GT(score(*m, big, "could you bring me the large plank"),
            score(*m, small, "could you bring me the large plank") + 3.0);
  // The goal's other name words are no values of a qualifier: they stay.
  EXPECT_EQ(m->encode("the stool repair").words, (std::vector<std::string>{"the", "stool", "repair"}));
}

// The domain's own type hierarchy is world knowledge too: planks, legs and
// brackets are declared `part`s, hammers and screwdrivers `tool`s, and the
// generated corpus sometimes names an object by such a supertype. WordNet
// does not call a leg or a bracket a part.
TEST(DomainCorpus, DeclaredSupertypesNameTheirObjects) {
  const AlignmentModel& m = *model_for(1);
  for (const char* part : {"leg1", "bracket1", "plank1"})
    for (const char* tool : {"hammer1", "screwdriver1"}) {
      const std::string p = std::string("(handover you me ") + part + ")";
      const std::string t = std::string("(handover you me ") + tool + ")";
      EXPECT_GT(score(m, p, "could you pass me the part"), score(m, t, "could you pass me the part") + 1.0)
          << part << " vs " << tool;
      EXPECT_GT(score(m, t, "could you pass me a tool"), score(m, p, "could you pass me a tool") + 1.0)
          << tool << " vs " << part;
    }
}

// Where a put leaves its object is said as a place ("on the bench"): with the
// putdown's destination declared (a pack derives it from the effects), the
// corpus has commands stating it and the model tells the places apart.
TEST(DomainCorpus, DestinationsAreSaidAsPlaces) {
  DomainDescription d = workshop(1);
  for (CommandActionRule& r : d.command_actions)
    if (r.action == "putdown") r.destination_arg = 3;
  const std::vector<TrainingPair> pairs = generate_domain_corpus(d, {});
  const bool stated = std::any_of(pairs.begin(), pairs.end(), [](const TrainingPair& p) {
    return p.command.find("(putdown you plank1) where") == 0 && p.command.find("(to plank1 ") != std::string::npos;
  });
  EXPECT_TRUE(stated);
  const std::shared_ptr<AlignmentModel> m = train_domain_model(d, {});
  const std::string bench = "(putdown you plank1) where (to plank1 bench)";
  const std::string rack = "(putdown you plank1) where (to plank1 rack)";
  EXPECT_GT(score(*m, bench, "could you put the plank on the bench"),
            score(*m, rack, "could you put the plank on the bench") + 1.0);
  EXPECT_GT(score(*m, rack, "take the plank over to the rack please"),
            score(*m, bench, "take the plank over to the rack please") + 1.0);
}

// Colour binding, generalised: a size said of a noun of another type does not
// count for an object of this type ("the big hammer" is no big plank).
TEST(DomainCorpus, SizeBindsToItsNounLikeAColour) {
  const AlignmentModel& m = *model_for(1);
  const std::string u = "could you bring me the big hammer";
  std::printf("[%s]\n", u.c_str());
  EXPECT_EQ(best_of(m, u,
                    {"(handover you me hammer1) where (issize hammer1 big)",
                     "(handover you me plank1) where (issize plank1 big)",
                     "(handover you me screwdriver1) where (issize screwdriver1 small)"}),
            "(handover you me hammer1) where (issize hammer1 big)");
}

// Contradiction, generalised: "small" contradicts a plank the command knows
// to be big, as "red" does a blue door; but a qualifier of another kind
// ("wooden", a material) says nothing against a known size.
TEST(DomainCorpus, QualifierValuesContradictOnlyTheirOwnKind) {
  const AlignmentModel& m = *model_for(1);
  const std::string small = "pick up the small plank";
  const double known_big = score(m, "(pickup you plank1) where (issize plank1 big)", small);
  const double size_open = score(m, "(pickup you plank1) where (ismaterial plank1 wooden)", small);
  const std::string wooden = "pick up the wooden plank";
  const double wooden_size_known = score(m, "(pickup you plank1) where (issize plank1 big)", wooden);
  const double wooden_nothing_known = score(m, "(pickup you plank1)", wooden);
  const double wooden_metal = score(m, "(pickup you plank1) where (ismaterial plank1 metal)", wooden);
  std::printf("[contradiction] small vs known big %.2f, vs open size %.2f; wooden vs known size %.2f, "
              "vs nothing known %.2f, vs known metal %.2f\n",
              known_big, size_open, wooden_size_known, wooden_nothing_known, wooden_metal);
  // (Measured: 2.5, 1.1, 4.6 and 3.5 nats; a contradiction costs up to
  // log(1 / kContradictedColour) = 3.9 nats.)
  EXPECT_GT(size_open - known_big, 2.0);
  // A known size costs "wooden" no more than the size's unspoken mention ...
  EXPECT_LT(std::abs(wooden_size_known - wooden_nothing_known), 1.5);
  // ... while a known other material contradicts it.
  EXPECT_GT(wooden_nothing_known - wooden_metal, 3.0);
  EXPECT_GT(wooden_size_known - wooden_metal, 2.0);
}

// The entry point for inference code: an embedded model with the generated
// corpus instead of the paper domains' files, scoring through prompts.
TEST(DomainCorpus, EmbeddedModelOptionsForADomainWithoutACorpus) {
  EmbeddedModelOptions o = embedded_options_for_domain(workshop(1));
  o.cache_dir = "off";
  EXPECT_TRUE(o.corpus_files.empty());
  EXPECT_FALSE(o.extra_corpus.empty());
  EmbeddedLanguageModel lm(o);
  const std::string few = "Input: (pickup you leg1) where (issize leg1 small)\nOutput: Can you get the small leg?\n";
  auto prompt = [&](const std::string& cmd) { return few + "Input: " + cmd + "\nOutput:"; };
  const double big = lm.score_one(prompt("(handover you me plank1) where (issize plank1 big)"), " Could you bring me the big plank?\n");
  const double small = lm.score_one(prompt("(handover you me plank1) where (issize plank1 small)"), " Could you bring me the big plank?\n");
  EXPECT_GT(big, small + 3.0);
  // The paper domains' words are not in its vocabulary: it trained on the workshop alone.
  const auto model = lm.model_for_prompt(prompt("(pickup you plank1)"));
  EXPECT_EQ(model->encode("gem").ids.at(0), -1);
  EXPECT_GE(model->encode("plank").ids.at(0), 0);
}

TEST(DomainCorpus, TypesMeanTheSenseTheirSupertypesSay) {
  WordNetLexicon& wn = WordNetLexicon::instance();
  // WordNet's first senses: a saw is a saying, a wrench an injury, a spade a
  // playing card. Declared as tools, they are the tools.
  const std::map<std::string, std::string> tools = {{"saw", "tool"},    {"wrench", "tool"}, {"spade", "tool"},
                                                    {"hammer", "tool"}, {"tool", "item"},   {"item", "object"}};
  const NounSenses senses = wn.domain_noun_senses(tools, {"saw", "wrench", "spade", "hammer", "tool", "item"});
  const auto gloss_word = [&](const std::string& type) {
    const auto it = senses.find(type);
    return it == senses.end() ? -1 : it->second;
  };
  EXPECT_GE(gloss_word("saw"), 1);     // a hand saw or a power saw
  EXPECT_EQ(gloss_word("wrench"), 2);  // "wrench, spanner"
  EXPECT_EQ(gloss_word("spade"), 1);   // "a sturdy hand shovel"
  EXPECT_EQ(gloss_word("tool"), -1);   // its first sense is already the implement
  // Among sayings the saw stays a saying.
  const NounSenses sayings =
      wn.domain_noun_senses({{"saw", "saying"}, {"motto", "saying"}, {"saying", "object"}}, {"saw", "motto"});
  EXPECT_EQ(sayings.count("saw"), 0u);
  // The noun's lexical base follows the sense: the spanner and the tool it is.
  const auto has = [](const WordDistribution& d, const std::string& w) {
    return std::any_of(d.begin(), d.end(), [&](const auto& e) { return e.first == w; });
  };
  EXPECT_FALSE(has(wn.noun_base("wrench", false), "spanner"));
  EXPECT_TRUE(has(wn.noun_base("wrench", false, 2), "spanner"));
  EXPECT_TRUE(has(wn.noun_base("wrench", false, 2), "tool"));
  // The workshop declares its wrench a tool, so the generated corpus may call it a spanner.
  EXPECT_EQ(domain_noun_senses(workshop(2)).at("wrench"), 2);
}

TEST(DomainCorpus, TypesNamedInThePluralAreFoundUnderTheirLemma) {
  WordNetLexicon& wn = WordNetLexicon::instance();
  const auto weight = [](const WordDistribution& d, const std::string& w) {
    for (const auto& [word, p] : d)
      if (word == w) return p;
    return 0.0;
  };
  // WordNet files oats under "oat": the name alone found nothing, so "cereal"
  // named rice and never oats.
  const WordDistribution oats = wn.noun_base("oats", false);
  EXPECT_GT(weight(oats, "cereal") + weight(oats, "cereals"), 0.0);
  EXPECT_GT(weight(oats, "oats"), weight(oats, "oat"));  // said in the plural
  const WordDistribution rice = wn.noun_base("rice", false);
  EXPECT_GT(weight(rice, "cereal") + weight(rice, "cereals"), 0.0);
  // Among garden supplies (substances) seeds stay seeds: the sense of
  // "seed" nearest the substances is a body fluid, not a kind of thing the
  // context holds.
  const NounSenses garden = wn.domain_noun_senses(
      {{"seeds", "supply"}, {"compost", "supply"}, {"fertilizer", "supply"}, {"mulch", "supply"},
       {"twine", "supply"}, {"supply", "item"}, {"item", "object"}},
      {"seeds", "compost", "fertilizer", "mulch", "twine"});
  EXPECT_EQ(garden.count("seeds"), 0u);
  EXPECT_NE(wn.noun_gloss("seeds", 0).find("fruit"), std::string::npos);
}

TEST(DomainCorpus, TheSpannerIsTheWorkshopsWrench) {
  const AlignmentModel& m = *model_for(2);
  std::printf("[could you pass me the spanner]\n");
  // The wrench last: a tie would go to the hammer.
  EXPECT_EQ(best_of(m, "could you pass me the spanner",
                    {"(handover you me hammer1)", "(handover you me plank1)", "(handover you me wrench1)"}),
            "(handover you me wrench1)");
  EXPECT_GT(score(m, "(handover you me wrench1)", "could you pass me the spanner"),
            score(m, "(handover you me hammer1)", "could you pass me the spanner") + 2.0);
}

}  // namespace
}  // namespace clips::lm
