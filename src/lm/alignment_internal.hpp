#pragma once
// Internals shared by the files of the alignment model (alignment_model.cpp:
// the probability model; english_reader.cpp: reading an utterance's tokens;
// alignment_training.cpp: EM; alignment_snapshot.cpp: the cache format). Not
// part of the model's interface: include only from those files.
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "lm/alignment_model.hpp"
#include "lm/wordnet_lexicon.hpp"

namespace clips::lm {


// Mixture weights of the word process (see the header). They are fixed rather
// than learned: with a few hundred short sentences EM would happily move mass
// between sources in ways that help fit but hurt discrimination.
inline constexpr double kPiBackground = 0.5;
inline constexpr double kPiAgent = 0.1;
inline constexpr double kPiContent = 0.4;
inline constexpr double kGenericShare = 0.08;  // share of GEN inside Content when groups are active
inline constexpr double kMention = 0.85;       // prior mean of the rho (Beta pseudo-counts 2)
inline constexpr double kRequestClause = 0.8;
// A clause whose subject says whose part it is ("can you ...", "you bring
// ...", "I'll get ...", "let me ...") is of that type with this probability.
inline constexpr double kMarkedClause = 0.99;
// In a clause announcing the speaker's own step, the anchor of a listener's
// group is scaled by this (a deficient factor, like the colour binding's).
// Dev halves: 0.02 and 0.1 gave the same precision and recall.
inline constexpr double kOffRoleAnchor = 0.1;
inline constexpr size_t kMaxAnchors = 4;  // action groups whose mention requires an anchor token
inline constexpr int kMaxEnumeratedGroups = 10;  // units; beyond this all are taken as mentioned
// Log-probability below which a token's sources are rescaled. The clause
// products fold into logs once below 1e-200 (about e^-460), so a factor must
// stay above about e^-248 for the product not to underflow first: -200 leaves
// room for the mixture weights.
inline constexpr double kLogTinyToken = -200;

// Field weights inside a group, renormalised over the fields present.
inline constexpr double kWeightVerb = 0.3;
inline constexpr double kWeightNoun = 0.35;
inline constexpr double kWeightAttribute = 0.25;
inline constexpr double kWeightNumber = 0.1;
inline constexpr double kWeightFunction = 0.05;  // what the object is for (WordNetLexicon::function_words)
inline constexpr double kWeightRecipient = 0.3;  // relative to a group's fields, when mentioned

// Dirichlet strengths of the lexical bases.
inline constexpr double kKappaContent = 6.0;
inline constexpr double kKappaAgent = 6.0;
inline constexpr double kKappaGeneric = 20.0;
inline constexpr double kKappaBackground = 30.0;
inline constexpr double kKappaLength = 8.0;
inline constexpr double kLengthBaseShare = 0.1;  // least weight of the length base in any bucket
inline constexpr double kLengthSpread = 0.2;     // half-width of the length smoothing, relative
inline constexpr int kLengthSpreadFrom = 10;     // shorter lengths are frequent in training: kept as counted
inline constexpr double kBaseFloor = 0.03;     // uniform share inside each table's prior base
inline constexpr double kInitialFloor = 0.5;   // uniform share for the first E-step
inline constexpr double kAlphaPriorCopy = 8.0;  // Beta prior on the copy probability
inline constexpr double kAlphaPriorOther = 1.0;

inline constexpr int kMaxLen = 256;
inline constexpr int kMaxActionsBucket = 5;
inline constexpr double kUnigramShare = 0.1;  // background share kept on raw token frequencies
// Background share spelled out by the character model, whatever the training
// counts say. The corpus is generated from templates (about 240 word types in
// 10k tokens), so Dirichlet smoothing alone leaves a word it never had about
// 0.3% of the background; real speakers pad requests with such words ("would
// it be possible", "as well"). The empty-command prompt spells every
// open-class word with the same character model at half its mass, so without
// this share each unseen filler word cost a command about 5.7 nats against
// that prompt and padded requests went to goals that need no help. With it
// the cost is about 2.3 nats (log 0.5 / (0.5 * (0.1 + 0.9 * 0.003))).
inline constexpr double kNovelWordShare = 0.1;
inline constexpr int kCharSymbols = 36;  // a-z, 0-9; index 36 = end of word

inline int char_index(char c) {
  if (c >= 'a' && c <= 'z') return c - 'a';
  if (c >= '0' && c <= '9') return 26 + (c - '0');
  return -1;
}

inline int actions_bucket(int a) { return std::clamp(a, 0, kMaxActionsBucket); }

// Lexical class bits of a word, for reading noun phrases and their modifiers.
inline constexpr uint8_t kWordFunction = 1;     // closed class (is_function_word)
inline constexpr uint8_t kWordNoun = 2;         // content word, noun-like (WordNet) or unknown
inline constexpr uint8_t kWordVerb = 4;         // content word, verb-like
inline constexpr uint8_t kWordModifier = 8;     // attribute value (colour) or adjective
inline constexpr uint8_t kWordDeterminer = 16;  // opens a noun phrase ("a", "the", "this", "two")
inline constexpr uint8_t kWordPronoun = 32;     // a whole noun phrase ("me", "it")
inline constexpr uint8_t kWordPreposition = 64;  // may open a post-nominal modifier ("for", "to")
inline constexpr uint8_t kWordIndefinite = 128;  // "something": a noun phrase that takes modifiers
inline constexpr int kMaxModifierSpan = 5;       // tokens after the preposition, at most
// Colour binding (header, item 6).
inline constexpr double kTypedNoun = 1e-3;    // a head noun names a type if some noun table gives it this much
inline constexpr double kBindRatio = 0.1;     // the owner's type must give it this share of the best type's mass
inline constexpr double kMisboundCopy = 0.02; // copy weight left to a colour bound to another type's noun
inline constexpr int kMaxHeadDistance = 3;    // the head noun follows within this many tokens
// Contradicted colours (header, item 7).
inline constexpr double kContradictedColour = 0.02;  // factor on a token that miscolours the command's object
// Tokens after a negator that its scope may cover ("not the big red one").
inline constexpr size_t kMaxNegationScope = 6;

// Lexical class bits of a closed-class word (kWord* above); english_reader.cpp.
uint8_t closed_class_flags(std::string_view w);

// Tables and their lexical bases; alignment_model.cpp.
double length_base(int n, double mean);  // prior of utterance lengths around a mean
std::string verb_key(const FrameGroup& g);
std::string noun_key(const FrameGroup& g);
std::string number_key(int count);
// `senses`: the noun sense each type name means (NounSenses; the first when absent).
WordDistribution base_for_key(const std::string& key, const NounSenses& senses = {});

// ------------------------------------------------------------------------------------

struct AlignmentModel::Table {
  std::string key;
  std::vector<double> prob;                        // over the vocabulary
  std::unordered_map<std::string, double> extra;   // mass on words outside it (lazy tables)
  std::vector<std::pair<int, double>> base;        // lexical base over vocabulary ids
  double kappa = kKappaContent;

  double at(int id, const std::string& w) const {
    if (id >= 0) return prob[static_cast<size_t>(id)];
    if (extra.empty()) return 0.0;
    auto it = extra.find(w);
    return it == extra.end() ? 0.0 : it->second;
  }
};

struct AlignmentModel::Bound {
  struct Field {
    const Table* table;
    int table_index;  // -1 for lazily created tables (not trained)
    double weight;
    bool residual;    // the non-copy part of an attribute field
    bool verb = false;  // a verb field (kept inside modifier spans)
    bool number = false;  // a number field (bound to its head noun like a colour)
  };
  struct Copy {
    int id;
    std::string word;
    double weight;
  };
  // A mentionable unit: an action group, or the recipient ("me") of a
  // hand-over group, which the speaker may or may not put into words.
  struct Group {
    bool speaker;
    bool to_speaker = false;  // action group handing its objects to the speaker
    int kind;         // 0 = action group, 1 = recipient, 2 = attribute value, 3 = a place's number
    int parent = -1;  // for an optional unit: index of its action group
    double unit_weight = 0;  // its weight relative to the group's own fields (which sum to 1)
    double log_on, log_off;
    double nonverb_weight = 0;  // action group: weight of its noun/number fields (M in modifiers)
    // Attribute unit: the noun tables of its object's type (singular, plural),
    // for colour binding; null when the group has no typed object.
    const Table* type_nouns[2] = {nullptr, nullptr};
    std::vector<Field> fields;
    std::vector<Copy> copies;
  };
  std::vector<Group> groups;
  int num_actions = 0;
};

// Per-token source probabilities of one utterance under one bound command;
// p_group[g * n + i] is unit g's own emission at token i.
struct AlignmentModel::TokenSources {
  std::vector<double> p_bg, p_you, p_me, p_gen, p_mod, p_group;
};

struct AlignmentModel::Counts {
  std::vector<std::vector<double>> table;  // per trained table, per word id
  std::vector<double> bg;
  double copy = 0;
  double non_copy = 0;
  double mention_on[4] = {0, 0, 0, 0};
  double mention_all[4] = {0, 0, 0, 0};
  std::vector<std::vector<double>> length;  // [bucket][n]
};

}  // namespace clips::lm
