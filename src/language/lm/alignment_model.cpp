#include "language/lm/alignment_model.hpp"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <string_view>
#include <unordered_set>

#include "language/lm/language_model.hpp"
#include "language/lm/utterance_tokens.hpp"
#include "language/lm/wordnet_lexicon.hpp"
#include "util/hash.hpp"

namespace clips::lm {
namespace {

// Mixture weights of the word process (see the header). They are fixed rather
// than learned: with a few hundred short sentences EM would happily move mass
// between sources in ways that help fit but hurt discrimination.
constexpr double kPiBackground = 0.5;
constexpr double kPiAgent = 0.1;
constexpr double kPiContent = 0.4;
constexpr double kGenericShare = 0.08;  // share of GEN inside Content when groups are active
constexpr double kMention = 0.85;       // prior mean of the rho (Beta pseudo-counts 2)
constexpr double kRequestClause = 0.8;
constexpr size_t kMaxAnchors = 4;  // action groups whose mention requires an anchor token
constexpr int kMaxEnumeratedGroups = 10;  // units; beyond this all are taken as mentioned
// Log-probability below which a token's sources are rescaled. The clause
// products fold into logs once below 1e-200 (about e^-460), so a factor must
// stay above about e^-248 for the product not to underflow first: -200 leaves
// room for the mixture weights.
constexpr double kLogTinyToken = -200;

// Field weights inside a group, renormalised over the fields present.
constexpr double kWeightVerb = 0.3;
constexpr double kWeightNoun = 0.35;
constexpr double kWeightAttribute = 0.25;
constexpr double kWeightNumber = 0.1;
constexpr double kWeightRecipient = 0.3;  // relative to a group's fields, when mentioned

// Dirichlet strengths of the lexical bases.
constexpr double kKappaContent = 6.0;
constexpr double kKappaAgent = 6.0;
constexpr double kKappaGeneric = 20.0;
constexpr double kKappaBackground = 30.0;
constexpr double kKappaLength = 8.0;
constexpr double kLengthBaseShare = 0.1;  // least weight of the length base in any bucket
constexpr double kLengthSpread = 0.2;     // half-width of the length smoothing, relative
constexpr int kLengthSpreadFrom = 10;     // shorter lengths are frequent in training: kept as counted
constexpr double kBaseFloor = 0.03;     // uniform share inside each table's prior base
constexpr double kInitialFloor = 0.5;   // uniform share for the first E-step
constexpr double kAlphaPriorCopy = 8.0;  // Beta prior on the copy probability
constexpr double kAlphaPriorOther = 1.0;

constexpr int kMaxLen = 256;
constexpr int kMaxActionsBucket = 5;
constexpr double kUnigramShare = 0.1;  // background share kept on raw token frequencies
// Background share spelled out by the character model, whatever the training
// counts say. The corpus is generated from templates (about 240 word types in
// 10k tokens), so Dirichlet smoothing alone leaves a word it never had about
// 0.3% of the background; real speakers pad requests with such words ("would
// it be possible", "as well"). The empty-command prompt spells every
// open-class word with the same character model at half its mass, so without
// this share each unseen filler word cost a command about 5.7 nats against
// that prompt and padded requests went to goals that need no help. With it
// the cost is about 2.3 nats (log 0.5 / (0.5 * (0.1 + 0.9 * 0.003))).
constexpr double kNovelWordShare = 0.1;
constexpr int kCharSymbols = 36;  // a-z, 0-9; index 36 = end of word

int char_index(char c) {
  if (c >= 'a' && c <= 'z') return c - 'a';
  if (c >= '0' && c <= '9') return 26 + (c - '0');
  return -1;
}

int actions_bucket(int a) { return std::clamp(a, 0, kMaxActionsBucket); }

// Lexical class bits of a word, for reading noun phrases and their modifiers.
constexpr uint8_t kWordFunction = 1;     // closed class (is_function_word)
constexpr uint8_t kWordNoun = 2;         // content word, noun-like (WordNet) or unknown
constexpr uint8_t kWordVerb = 4;         // content word, verb-like
constexpr uint8_t kWordModifier = 8;     // attribute value (colour) or adjective
constexpr uint8_t kWordDeterminer = 16;  // opens a noun phrase ("a", "the", "this", "two")
constexpr uint8_t kWordPronoun = 32;     // a whole noun phrase ("me", "it")
constexpr uint8_t kWordPreposition = 64;  // may open a post-nominal modifier ("for", "to")
constexpr uint8_t kWordIndefinite = 128;  // "something": a noun phrase that takes modifiers
constexpr int kMaxModifierSpan = 5;       // tokens after the preposition, at most
// Colour binding (header, item 6).
constexpr double kTypedNoun = 1e-3;    // a head noun names a type if some noun table gives it this much
constexpr double kBindRatio = 0.1;     // the owner's type must give it this share of the best type's mass
constexpr double kMisboundCopy = 0.02; // copy weight left to a colour bound to another type's noun
constexpr int kMaxHeadDistance = 3;    // the head noun follows within this many tokens
// Contradicted colours (header, item 7).
constexpr double kContradictedColour = 0.02;  // factor on a token that miscolours the command's object

bool is_relative_pronoun(std::string_view w) { return w == "that" || w == "which"; }

uint8_t closed_class_flags(std::string_view w) {
  static const std::set<std::string_view> determiners = {
      "a",    "an",   "the",   "this",    "that", "these", "those", "some",  "any",  "my",
      "your", "our",  "his",   "her",     "their", "its",  "another", "each", "every", "both",
      "one",  "two",  "three", "four",    "five",  "six",  "no"};
  static const std::set<std::string_view> pronouns = {"me", "you", "us", "him", "her", "them",
                                                      "it", "myself", "yourself", "ourselves"};
  static const std::set<std::string_view> indefinite = {"something", "anything", "everything", "someone"};
  uint8_t f = 0;
  if (is_function_word(w)) f |= kWordFunction;
  if (determiners.count(w) != 0) f |= kWordDeterminer;
  if (pronouns.count(w) != 0) f |= kWordPronoun;
  if (w == "for" || w == "to") f |= kWordPreposition;
  if (indefinite.count(w) != 0) f |= kWordIndefinite;
  return f;
}

double log_poisson(int n, double mu) {
  return n * std::log(mu) - mu - std::lgamma(n + 1.0);
}

// Base distribution of lengths: mostly Poisson around the mean, with a
// geometric component so long utterances are never impossible.
double length_base(int n, double mean) {
  const double p = 1.0 / 16.0;
  return 0.8 * std::exp(log_poisson(n, mean)) + 0.2 * p * std::pow(1 - p, n);
}

WordDistribution agent_base(bool speaker) {
  if (speaker) {
    return {{"i", 0.3},     {"will", 0.15},   {"am", 0.15}, {"going", 0.1}, {"let", 0.05},
            {"me", 0.05},   {"myself", 0.05}, {"we", 0.05}, {"now", 0.05}, {"gonna", 0.05}};
  }
  return {{"you", 0.25}, {"can", 0.15}, {"could", 0.15}, {"would", 0.1}, {"please", 0.1},
          {"will", 0.05}, {"help", 0.05}, {"need", 0.05}, {"want", 0.05}, {"go", 0.05}};
}

WordDistribution number_base(int count) {
  static const char* names[] = {"zero", "one", "two", "three", "four", "five",
                                "six",  "seven", "eight", "nine", "ten"};
  WordDistribution d;
  if (count <= 10) {
    d.emplace_back(names[count], 0.35);
    d.emplace_back(std::to_string(count), 0.05);
  }
  if (count == 2) {
    d.emplace_back("both", 0.25);
    d.emplace_back("pair", 0.03);
    d.emplace_back("couple", 0.02);
  } else {
    d.emplace_back("all", 0.2);
    d.emplace_back("every", 0.05);
  }
  d.emplace_back("these", 0.05);
  d.emplace_back("those", 0.05);
  d.emplace_back("some", 0.1);
  d.emplace_back("multiple", 0.02);
  d.emplace_back("more", 0.02);
  double z = 0;
  for (auto& [w, p] : d) z += p;
  for (auto& [w, p] : d) p /= z;
  return d;
}

std::string verb_key(const FrameGroup& g) {
  return "V:" + g.action + "/" + g.agent + (g.to_speaker ? "/to-me" : "");
}
std::string noun_key(const FrameGroup& g) {
  return "N:" + g.type + (g.count >= 2 ? "/pl" : "/sg");
}
std::string number_key(int count) { return "Q:" + std::to_string(std::min(count, 10)); }

// Lexical base of a table key (the keys above plus the fixed sources).
WordDistribution base_for_key(const std::string& key) {
  if (key == "A:you") return agent_base(false);
  if (key == "A:me") return agent_base(true);
  if (key == "P:me") {
    return {{"me", 0.6}, {"my", 0.08}, {"here", 0.1}, {"way", 0.05}, {"myself", 0.02},
            {"over", 0.05}, {"to", 0.05}, {"back", 0.05}};
  }
  if (key.rfind("Q:", 0) == 0) return number_base(std::stoi(key.substr(2)));
  if (key.rfind("V:", 0) == 0) {
    const size_t slash = key.find('/');
    const std::string action = key.substr(2, slash - 2);
    const bool to_me = key.find("/to-me") != std::string::npos;
    return WordNetLexicon::instance().verb_base(action, to_me);
  }
  if (key.rfind("N:", 0) == 0) {
    const size_t slash = key.rfind('/');
    return WordNetLexicon::instance().noun_base(key.substr(2, slash - 2), key.substr(slash) == "/pl");
  }
  return {};  // GEN and R get their bases from the trainer
}

}  // namespace

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
    int kind;         // 0 = action group, 1 = recipient, 2 = attribute value
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

struct AlignmentModel::Counts {
  std::vector<std::vector<double>> table;  // per trained table, per word id
  std::vector<double> bg;
  double copy = 0;
  double non_copy = 0;
  double mention_on[3] = {0, 0, 0};
  double mention_all[3] = {0, 0, 0};
  std::vector<std::vector<double>> length;  // [bucket][n]
};

AlignmentModel::AlignmentModel() = default;
AlignmentModel::~AlignmentModel() = default;

int AlignmentModel::add_word(const std::string& w) {
  auto [it, inserted] = word_ids_.emplace(w, static_cast<int>(words_.size()));
  if (inserted) words_.push_back(w);
  return it->second;
}

int AlignmentModel::table_index(const std::string& key) {
  auto it = table_ids_.find(key);
  if (it != table_ids_.end()) return it->second;
  auto t = std::make_unique<Table>();
  t->key = key;
  tables_.push_back(std::move(t));
  const int id = static_cast<int>(tables_.size()) - 1;
  table_ids_.emplace(key, id);
  if (key.rfind("N:", 0) == 0) noun_tables_.push_back(id);
  return id;
}

double AlignmentModel::char_prob(const std::string& w) const {
  if (w.empty()) return 0.0;
  int prev = char_index(w[0]);
  if (prev < 0) return 0.0;
  double p = char_first_[static_cast<size_t>(prev)];
  for (size_t i = 1; i < w.size(); ++i) {
    const int c = char_index(w[i]);
    if (c < 0) return 0.0;
    p *= char_next_[static_cast<size_t>(prev * (kCharSymbols + 1) + c)];
    prev = c;
  }
  return p * char_next_[static_cast<size_t>(prev * (kCharSymbols + 1) + kCharSymbols)];
}

// The same model in log space: a long word's product of per-letter factors
// leaves the double range (about 1e-308) after some two hundred letters.
double AlignmentModel::char_log_prob(const std::string& w) const {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  if (w.empty()) return kNone;
  int prev = char_index(w[0]);
  if (prev < 0) return kNone;
  double lp = std::log(char_first_[static_cast<size_t>(prev)]);
  for (size_t i = 1; i < w.size(); ++i) {
    const int c = char_index(w[i]);
    if (c < 0) return kNone;
    lp += std::log(char_next_[static_cast<size_t>(prev * (kCharSymbols + 1) + c)]);
    prev = c;
  }
  return lp + std::log(char_next_[static_cast<size_t>(prev * (kCharSymbols + 1) + kCharSymbols)]);
}

double AlignmentModel::log_prob_unprimed(const EncodedUtterance& u, bool complete) const {
  double lp = length_log_prob(0, static_cast<int>(u.words.size()), complete);
  for (size_t i = 0; i < u.words.size(); ++i) {
    const int id = u.ids[i];
    double closed = 0;
    if (id >= 0 && (word_flags_[static_cast<size_t>(id)] & kWordFunction) && closed_mass_ > 0)
      closed = bg_[static_cast<size_t>(id)] / closed_mass_;
    if (id >= 0 && !(word_flags_[static_cast<size_t>(id)] & (kWordNoun | kWordVerb | kWordModifier)) &&
        char_index(u.words[i][0]) < 0 && closed_mass_ > 0)
      closed = bg_[static_cast<size_t>(id)] / closed_mass_;  // punctuation
    const double p = 0.5 * closed + 0.5 * char_prob(u.words[i]);
    if (p > 0) {
      lp += std::log(p);
    } else if (closed == 0) {
      lp += std::log(0.5) + char_log_prob(u.words[i]);  // spelled out, below the double range
    } else {
      return -std::numeric_limits<double>::infinity();
    }
  }
  return lp;
}

double AlignmentModel::bg_prob(int id, const std::string& w) const {
  if (id >= 0) return bg_[static_cast<size_t>(id)];
  return bg_unknown_scale_ * char_prob(w);
}

namespace {

// One edit apart: a substitution, an insertion or deletion, or a swap of two
// neighbouring letters ("yelow", "kye", "bleu" from "yellow", "key", "blue").
bool one_edit_apart(const std::string& a, const std::string& b) {
  if (a == b) return false;
  if (a.size() == b.size()) {
    size_t i = 0;
    while (a[i] == b[i]) ++i;
    if (a.compare(i + 1, std::string::npos, b, i + 1, std::string::npos) == 0) return true;  // substitution
    return i + 1 < a.size() && a[i] == b[i + 1] && a[i + 1] == b[i] &&
           a.compare(i + 2, std::string::npos, b, i + 2, std::string::npos) == 0;  // swap
  }
  const std::string& l = a.size() > b.size() ? a : b;
  const std::string& s = a.size() > b.size() ? b : a;
  if (l.size() != s.size() + 1) return false;
  size_t i = 0;
  while (i < s.size() && l[i] == s[i]) ++i;
  return l.compare(i + 1, std::string::npos, s, i, std::string::npos) == 0;
}

// Runs of three or more equal letters cut to `keep` letters ("pleeease").
std::string shorten_runs(const std::string& w, size_t keep) {
  std::string out;
  for (size_t i = 0; i < w.size();) {
    size_t j = i;
    while (j < w.size() && w[j] == w[i]) ++j;
    out.append(j - i >= 3 ? keep : j - i, w[i]);
    i = j;
  }
  return out;
}

}  // namespace

// Spelling repair for a token the model has never seen. Elongated words
// ("neeed", "pleeease") are read with their letter runs shortened when that
// gives a known word. A word that WordNet does not know either is read as the
// content word of the vocabulary one edit away, the most frequent if several
// are: "yelow" -> "yellow", "kye" -> "key", "rd" -> "red" (a two-letter token
// only by a dropped letter). Real words stay as written ("soon" is never read
// as "spoon"), and so do function words and tokens with digits.
std::string AlignmentModel::respell(const std::string& w) const {
  if (w.size() < 2 || is_function_word(w)) return w;
  for (char ch : w)
    if (ch < 'a' || ch > 'z') return w;
  WordNetLexicon& wn = WordNetLexicon::instance();
  auto known = [&](const std::string& x) { return word_ids_.count(x) != 0 || is_function_word(x) || wn.knows(x); };
  const bool one_letter = w.find_first_not_of(w[0]) == std::string::npos;  // "zzzz" is no elongated word
  if (const std::string two = shorten_runs(w, 2); two != w && !one_letter) {
    if (known(two)) return two;
    if (const std::string one = shorten_runs(w, 1); known(one)) return one;
  }
  if (wn.knows(w)) return w;
  int best = -1;
  bool best_full = false;
  for (size_t id = 0; id < words_.size() && id < bg_.size() && id < word_flags_.size(); ++id) {
    const std::string& v = words_[id];
    if (v.size() < 3 || v.size() + 1 < w.size() || v.size() > w.size() + 1) continue;
    if (w.size() == 2 && v.size() != 3) continue;  // "rd", "gt": only a dropped letter
    const uint8_t f = word_flags_[id];
    if ((f & kWordFunction) != 0 || (f & (kWordNoun | kWordVerb | kWordModifier)) == 0) continue;
    if (!one_edit_apart(w, v)) continue;
    // A dropped letter is the commoner slip than an extra one ("glases" is
    // "glasses" rather than "glass"); among equals, the more frequent word.
    const bool full = v.size() >= w.size();
    if (best < 0 || full > best_full || (full == best_full && bg_[id] > bg_[static_cast<size_t>(best)])) {
      best = static_cast<int>(id);
      best_full = full;
    }
  }
  return best >= 0 ? words_[static_cast<size_t>(best)] : w;
}

std::string AlignmentModel::respelled(const std::string& w) const {
  {
    std::shared_lock lock(respell_mutex_);
    if (auto it = respelled_.find(w); it != respelled_.end()) return it->second;
  }
  std::string r = respell(w);
  std::unique_lock lock(respell_mutex_);
  if (respelled_.size() > (1u << 14)) respelled_.clear();  // bound memory in a long-running server
  respelled_.emplace(w, r);
  return r;
}

EncodedUtterance AlignmentModel::encode(const std::string& text) const {
  EncodedUtterance u;
  u.words = tokenize_utterance(text);
  u.ids.reserve(u.words.size());
  for (size_t i = 0; i < u.words.size(); ++i) {
    if (word_ids_.count(u.words[i]) == 0) u.words[i] = respelled(u.words[i]);
    auto it = word_ids_.find(u.words[i]);
    u.ids.push_back(it == word_ids_.end() ? -1 : it->second);
    if (is_clause_end(u.words[i])) u.clause_end.push_back(static_cast<int>(i) + 1);
  }
  if (u.clause_end.empty() || u.clause_end.back() != static_cast<int>(u.words.size())) {
    u.clause_end.push_back(static_cast<int>(u.words.size()));
  }
  mark_modifiers(u);
  mark_pronoun_antecedents(u);
  return u;
}

uint8_t AlignmentModel::word_flags(int id, const std::string& w) const {
  if (id >= 0 && static_cast<size_t>(id) < word_flags_.size()) return word_flags_[static_cast<size_t>(id)];
  // Unknown words: closed-class lists, else read as a noun (a name of something).
  const uint8_t f = closed_class_flags(w);
  return (f & kWordFunction) != 0 ? f : static_cast<uint8_t>(f | kWordNoun);
}

// For each object "it"/"them" in a clause that reads as a request (it has
// "you", or no "i"/"we" subject: "come get it open"), the closest
// colour-bearing noun phrase of an earlier clause is what the request is
// about. A simple recency rule: the reading only decides which role's
// objects a colour may contradict.
void AlignmentModel::mark_pronoun_antecedents(EncodedUtterance& u) const {
  // "it" before a verb of being or an auxiliary is the empty subject of "it
  // would be great if ...", which points back at nothing.
  static const std::unordered_set<std::string> dummy_next = {
      "is", "s", "was", "would", "will", "d", "might", "could", "should", "may", "must",
      "seems", "looks", "be", "has", "can", "does", "did", "sounds"};
  const size_t n = u.words.size();
  u.asked_for.assign(n, 0);
  if (u.noun_heads.size() != n) return;
  size_t clause_start = 0;
  for (size_t e : u.clause_end) {
    const size_t end = std::min(e, n);
    bool you = false, first_person = false, pronoun = false;
    for (size_t i = clause_start; i < end; ++i) {
      const std::string& w = u.words[i];
      you = you || w == "you";
      first_person = first_person || w == "i" || w == "we";
      const bool dummy = w == "it" && i + 1 < n && dummy_next.count(u.words[i + 1]) != 0;
      pronoun = pronoun || (w == "it" && !dummy) || w == "them";
    }
    if (pronoun && (you || !first_person)) {
      // The latest colour token before this clause that has a head noun.
      for (size_t i = clause_start; i-- > 0;) {
        if (u.noun_heads[i][0] >= 0 && i < u.ids.size() && u.ids[i] >= 0 &&
            static_cast<size_t>(u.ids[i]) < attribute_word_.size() && attribute_word_[static_cast<size_t>(u.ids[i])]) {
          u.asked_for[i] = 1;
          break;
        }
      }
    }
    clause_start = end;
  }
}

// Post-nominal prepositional modifiers, read left to right: a span opens after
// "for"/"to" whose preceding word heads a noun phrase (a noun after a
// determiner, possibly with adjectives between, or "something"), and covers the
// following determiners, pronouns, adjectives and participles up to and
// including the head noun or pronoun. A verb right after the preposition is an
// infinitive ("a key to open the door"): it ends the span, so its object is not
// inside it. The flag of token i depends only on tokens before i.
void AlignmentModel::mark_modifiers(EncodedUtterance& u) const {
  const size_t n = u.words.size();
  u.in_modifier.assign(n, 0);
  std::vector<uint8_t> f(n);
  for (size_t i = 0; i < n; ++i) f[i] = word_flags(u.ids[i], u.words[i]);
  auto heads_noun_phrase = [&](size_t j) {
    if ((f[j] & kWordIndefinite) != 0) return true;
    const bool one = u.words[j] == "one" || u.words[j] == "ones";
    if (!one && ((f[j] & kWordFunction) != 0 || (f[j] & kWordNoun) == 0)) return false;
    for (size_t back = 1; back <= 3 && back <= j; ++back) {
      const uint8_t g = f[j - back];
      if ((g & kWordDeterminer) != 0) return true;
      const bool modifier = (g & kWordModifier) != 0 || ((g & kWordFunction) == 0 && (g & kWordNoun) != 0 &&
                                                         (g & kWordVerb) == 0);
      if (!modifier) return false;
    }
    return false;
  };
  // Head nouns of adjectives and colours: the first following token that is
  // neither a closed-class word nor a modifier, if it is a noun and comes
  // within kMaxHeadDistance tokens without crossing a clause end.
  // Determiners and number words ("two", "both", "some") get their head noun
  // the same way, for the number binding of evaluate().
  u.noun_heads.assign(n, {-1, -1});
  for (size_t i = 0; i < n; ++i) {
    if ((f[i] & (kWordModifier | kWordDeterminer)) == 0) continue;
    for (size_t j = i + 1; j < n && j <= i + kMaxHeadDistance; ++j) {
      if (is_clause_end(u.words[j]) || (f[j] & kWordFunction) != 0) break;
      if ((f[j] & kWordModifier) != 0) continue;
      if ((f[j] & kWordNoun) != 0) u.noun_heads[i][0] = static_cast<int>(j);
      break;
    }
    // A colour placed after its noun ("pass me the key blue") describes the
    // noun just before it when no noun follows.
    const bool ends_phrase = i + 1 == n || is_clause_end(u.words[i + 1]) || (f[i + 1] & kWordFunction) != 0;
    if (u.noun_heads[i][0] < 0 && (f[i] & kWordModifier) != 0 && ends_phrase && i > 0 &&
        (f[i - 1] & kWordNoun) != 0 && (f[i - 1] & (kWordFunction | kWordModifier)) == 0)
      u.noun_heads[i][0] = static_cast<int>(i) - 1;
  }
  bool open = false;
  int k = 0;
  int anchor = -1;   // the noun the open span attaches to
  int purpose = -1;  // after "a key to open": that noun, for the verb's object
  int relative = -1;  // after "the key that": that noun, once the verb is read
  int pk = 0;
  for (size_t i = 0; i < n; ++i) {
    if (open) {
      u.in_modifier[i] = 1;
      if ((f[i] & kWordModifier) != 0) u.noun_heads[i][1] = anchor;
    }
    if (is_clause_end(u.words[i])) {
      open = false;
      purpose = relative = -1;
      continue;
    }
    if (purpose >= 0 && !open) {
      // The object of a purpose infinitive ("a key to open [this yellow
      // door]") is read as usual, but its colours may describe the key too.
      if ((f[i] & kWordModifier) != 0) u.noun_heads[i][1] = purpose;
      const bool np_word = (f[i] & kWordFunction) != 0 || (f[i] & kWordModifier) != 0;
      if (++pk > kMaxModifierSpan || !np_word) purpose = -1;
    }
    if (relative >= 0 && i > 0 && is_relative_pronoun(u.words[i - 1])) {
      purpose = relative;  // token i is the relative clause's verb
      pk = 0;
      relative = -1;
    }
    if (open) {
      ++k;
      const uint8_t g = f[i];
      if ((g & kWordPronoun) == 0 && k == 1 && (g & kWordVerb) != 0) {
        open = false;  // an infinitive's verb ("a key to open ..."): its object follows
        purpose = anchor;
        pk = 0;
      } else if ((g & kWordPronoun) != 0 || (k == 1 && (g & kWordVerb) != 0)) {
        open = false;  // a pronoun
      } else if ((g & kWordFunction) != 0 || (g & kWordModifier) != 0 ||
                 ((g & kWordVerb) != 0 && (g & kWordNoun) == 0)) {
        // Determiners, adjectives, colours and participles ("the locked door").
        open = k < kMaxModifierSpan;
      } else {
        open = false;  // the head noun, or an infinitive's verb
      }
    } else if ((f[i] & kWordPreposition) != 0 && i > 0 && heads_noun_phrase(i - 1)) {
      open = true;
      k = 0;
      anchor = static_cast<int>(i) - 1;
    } else if ((f[i] & kWordPreposition) != 0 && (i == 0 || is_clause_end(u.words[i - 1]))) {
      // Fronted: "For this yellow door, I need a key." The span opens as
      // usual (it depends on earlier tokens only); the noun it attaches to is
      // the first noun phrase of the next clause, read ahead like the heads.
      open = true;
      k = 0;
      anchor = -1;
      size_t j = i + 1;
      while (j < n && !is_clause_end(u.words[j])) ++j;
      for (++j; j < n && !is_clause_end(u.words[j]); ++j)
        if (heads_noun_phrase(j)) {
          anchor = static_cast<int>(j);
          break;
        }
    } else if (is_relative_pronoun(u.words[i]) && i > 0 && i + 1 < n && heads_noun_phrase(i - 1) &&
               (f[i + 1] & kWordVerb) != 0 && (f[i + 1] & kWordModifier) == 0) {
      // A relative clause ("the key that opens this yellow door") reads like
      // a purpose infinitive: its object's colours may describe the noun too.
      relative = static_cast<int>(i) - 1;  // takes effect after the verb
    }
  }
}

const AlignmentModel::Table* AlignmentModel::find_or_make_table(const std::string& key) const {
  if (auto it = table_ids_.find(key); it != table_ids_.end()) return tables_[static_cast<size_t>(it->second)].get();
  {
    std::shared_lock lock(lazy_mutex_);
    if (auto it = lazy_tables_.find(key); it != lazy_tables_.end()) return it->second.get();
  }
  // An element never seen in training: its emission is its lexical base alone.
  auto t = std::make_unique<Table>();
  t->key = key;
  t->prob.assign(words_.size(), 0.0);
  for (const auto& [w, p] : base_for_key(key)) {
    if (auto it = word_ids_.find(w); it != word_ids_.end()) {
      t->prob[static_cast<size_t>(it->second)] += p;
    } else {
      t->extra[w] += p;
    }
  }
  std::unique_lock lock(lazy_mutex_);
  auto [it, inserted] = lazy_tables_.emplace(key, std::move(t));
  return it->second.get();
}

std::shared_ptr<const AlignmentModel::Bound> AlignmentModel::bind(const std::string& command) const {
  const CommandFrame frame = parse_command_frame(command, "query command");
  auto b = std::make_shared<Bound>();
  b->num_actions = frame.num_actions;
  const Table* residual = tables_[static_cast<size_t>(table_ids_.at("R"))].get();
  const int residual_index = table_ids_.at("R");
  auto field_of = [&](const std::string& key, double weight) {
    const Table* t = find_or_make_table(key);
    auto it = table_ids_.find(key);
    return Bound::Field{t, it == table_ids_.end() ? -1 : it->second, weight, false};
  };
  for (const FrameGroup& g : frame.groups) {
    Bound::Group bg;
    bg.speaker = g.agent == "me";
    bg.to_speaker = g.to_speaker;
    bg.kind = 0;
    bg.log_on = std::log(mention_[0]);
    bg.log_off = std::log(1 - mention_[0]);
    // The group's own fields (verb, noun, number) sum to 1; each attribute value
    // (colour) is an optional unit of the group with a relative weight, so an
    // utterance that never says a colour pays the colour's mention odds rather
    // than merely diluting the group.
    const double z = kWeightVerb + (g.type.empty() ? 0 : kWeightNoun) + (g.count >= 2 ? kWeightNumber : 0);
    bg.fields.push_back(field_of(verb_key(g), kWeightVerb / z));
    bg.fields.back().verb = true;
    if (!g.type.empty()) bg.fields.push_back(field_of(noun_key(g), kWeightNoun / z));
    if (g.count >= 2) {
      bg.fields.push_back(field_of(number_key(g.count), kWeightNumber / z));
      bg.fields.back().number = true;
    }
    bg.nonverb_weight = 1.0 - kWeightVerb / z;
    if (!g.type.empty()) {
      bg.type_nouns[0] = find_or_make_table("N:" + g.type + "/sg");
      bg.type_nouns[1] = find_or_make_table("N:" + g.type + "/pl");
    }
    const int parent = static_cast<int>(b->groups.size());
    b->groups.push_back(std::move(bg));
    for (const std::string& a : g.attributes) {
      Bound::Group at;
      at.speaker = b->groups[static_cast<size_t>(parent)].speaker;
      at.kind = 2;
      at.parent = parent;
      at.unit_weight = kWeightAttribute / z / static_cast<double>(g.attributes.size());
      at.log_on = std::log(mention_[2]);
      at.log_off = std::log(1 - mention_[2]);
      auto it = word_ids_.find(a);
      at.copies.push_back(Bound::Copy{it == word_ids_.end() ? -1 : it->second, a, copy_alpha_});
      if (!g.type.empty()) {
        at.type_nouns[0] = find_or_make_table("N:" + g.type + "/sg");
        at.type_nouns[1] = find_or_make_table("N:" + g.type + "/pl");
      }
      at.fields.push_back(Bound::Field{residual, residual_index, 1 - copy_alpha_, true});
      b->groups.push_back(std::move(at));
    }
    if (g.to_speaker) {
      Bound::Group rec;
      rec.speaker = false;
      rec.kind = 1;
      rec.parent = parent;
      rec.unit_weight = kWeightRecipient / z;
      rec.log_on = std::log(mention_[1]);
      rec.log_off = std::log(1 - mention_[1]);
      rec.fields.push_back(field_of("P:me", 1.0));
      b->groups.push_back(std::move(rec));
    }
  }
  return b;
}

double AlignmentModel::length_log_prob(int actions, int n, bool complete) const {
  const size_t a = static_cast<size_t>(actions_bucket(actions));
  const std::vector<double>& pmf = length_[a];
  if (complete) {
    if (n <= kMaxLen) return std::log(pmf[static_cast<size_t>(n)]);
    return std::log(length_tail_scale_[a] * length_base(n, length_mean_[a]));
  }
  // P(N >= n): one minus the mass below n (the tail beyond kMaxLen is tiny but
  // positive; keep it so a long prefix is never impossible).
  double below = 0;
  for (int k = 0; k < std::min(n, kMaxLen + 1); ++k) below += pmf[static_cast<size_t>(k)];
  const double p = 1.0 / 16.0;
  const double floor_tail = length_tail_scale_[a] * 0.2 * std::pow(1 - p, std::max(n, kMaxLen + 1));
  return std::log(std::max(1.0 - below, floor_tail));
}

double AlignmentModel::evaluate(const Bound& c, const EncodedUtterance& u, bool complete,
                                Counts* counts, double weight) const {
  const size_t n = u.ids.size();
  const size_t G = c.groups.size();
  const Table& a_you = *tables_[static_cast<size_t>(table_ids_.at("A:you"))];
  const Table& a_me = *tables_[static_cast<size_t>(table_ids_.at("A:me"))];
  const Table& gen = *tables_[static_cast<size_t>(table_ids_.at("GEN"))];
  const Table& mod = *tables_[static_cast<size_t>(table_ids_.at("M"))];
  const bool have_spans = u.in_modifier.size() == n;
  const bool have_heads = u.noun_heads.size() == n;

  // The action groups a clause of each type talks about (header, item 4): a
  // request those of the listener; a statement the speaker's own, and what
  // is handed to the speaker ("I'm in need of the blue key").
  auto in_role = [](const Bound::Group& grp, bool statement) {
    return statement ? grp.speaker || grp.to_speaker : !grp.speaker;
  };

  // Colour binding (header, item 6): the share of its copy weight that
  // attribute unit g keeps at token i.
  auto bind_factor = [&](const Bound::Group& grp, size_t i) {
    if (!have_heads || grp.type_nouns[0] == nullptr) return 1.0;
    bool typed = false;
    for (int j : u.noun_heads[i]) {
      if (j < 0) continue;
      const int hid = u.ids[static_cast<size_t>(j)];
      const std::string& hw = u.words[static_cast<size_t>(j)];
      double best = 0;
      for (int t : noun_tables_) best = std::max(best, tables_[static_cast<size_t>(t)]->at(hid, hw));
      if (best < kTypedNoun) return 1.0;  // "one", "thing": says nothing about the type
      typed = true;
      const double own = std::max(grp.type_nouns[0]->at(hid, hw), grp.type_nouns[1]->at(hid, hw));
      if (own >= kBindRatio * best) return 1.0;
    }
    return typed ? kMisboundCopy : 1.0;
  };

  // Contradicted colours (header, item 7): contra[2 * i + t] is the factor on
  // token i in a clause of type t (0: request, groups of "you"; 1: statement,
  // groups of "me").
  std::vector<double> contra(2 * n, 1.0);
  if (have_heads) {
    for (size_t i = 0; i < n; ++i) {
      const int id = u.ids[i];
      if (id < 0 || static_cast<size_t>(id) >= attribute_word_.size() || !attribute_word_[static_cast<size_t>(id)])
        continue;
      for (int t = 0; t < 2; ++t) {
        bool typed = false, contradicted = true;
        for (int j : u.noun_heads[i]) {
          if (j < 0) continue;
          const int hid = u.ids[static_cast<size_t>(j)];
          const std::string& hw = u.words[static_cast<size_t>(j)];
          double best = 0;
          for (int tb : noun_tables_) best = std::max(best, tables_[static_cast<size_t>(tb)]->at(hid, hw));
          if (best < kTypedNoun) {
            contradicted = false;  // "one", "thing": may be anything of any colour
            break;
          }
          typed = true;
          // The command's objects this head can name, in this clause's role.
          bool named = false, consistent = false;
          for (size_t g = 0; g < G; ++g) {
            const Bound::Group& grp = c.groups[g];
            // A colour a later request points back to ("... this red door,
            // could you open it?") names an object of the request's role.
            const bool statement = t == 1 && !(i < u.asked_for.size() && u.asked_for[i]);
            if (grp.kind != 0 || !in_role(grp, statement) || grp.type_nouns[0] == nullptr) continue;
            const double own = std::max(grp.type_nouns[0]->at(hid, hw), grp.type_nouns[1]->at(hid, hw));
            if (own < kBindRatio * best) continue;
            named = true;
            bool coloured = false;
            for (size_t k = 0; k < G; ++k) {
              const Bound::Group& unit = c.groups[k];
              if (unit.parent != static_cast<int>(g) || unit.kind != 2) continue;
              coloured = true;
              for (const Bound::Copy& cp : unit.copies) consistent = consistent || cp.id == id;
            }
            consistent = consistent || !coloured;  // a colourless object may be any colour
          }
          if (!named || consistent) {
            contradicted = false;
            break;
          }
        }
        if (typed && contradicted) contra[2 * i + static_cast<size_t>(t)] = kContradictedColour;
      }
    }
  }

  // Per-token source probabilities; p_group[g * n + i] is unit g's own emission
  // (its fields' weights sum to 1 for an action group; for an optional unit
  // such as a recipient it is that unit's table alone).
  // Inside a modifier span an action group's noun and number fields give way to M.
  std::vector<double> p_bg(n), p_you(n), p_me(n), p_gen(n), p_mod(n, 0.0), p_group(n * G);
  for (size_t i = 0; i < n; ++i) {
    const int id = u.ids[i];
    const std::string& w = u.words[i];
    p_bg[i] = bg_prob(id, w);
    p_you[i] = a_you.at(id, w);
    p_me[i] = a_me.at(id, w);
    p_gen[i] = gen.at(id, w);
    const bool in_mod = have_spans && u.in_modifier[i] != 0;
    if (in_mod) p_mod[i] = mod.at(id, w);
    for (size_t g = 0; g < G; ++g) {
      double v = 0;
      if (in_mod && c.groups[g].kind == 0) {
        for (const Bound::Field& f : c.groups[g].fields) {
          if (f.verb) v += f.weight * f.table->at(id, w);
        }
        p_group[g * n + i] = v + c.groups[g].nonverb_weight * p_mod[i];
        continue;
      }
      for (const Bound::Field& f : c.groups[g].fields)
        v += f.weight * f.table->at(id, w) * (f.number ? bind_factor(c.groups[g], i) : 1.0);
      for (const Bound::Copy& cp : c.groups[g].copies) {
        if (id >= 0 ? id == cp.id : w == cp.word) v += cp.weight * bind_factor(c.groups[g], i);
      }
      p_group[g * n + i] = v;
    }
  }

  // A very long unknown word's background probability is below the double
  // range (one character-model factor per letter), and so would be every
  // mixture at its token. All sources of such a token are divided by a common
  // factor instead, which every forward pass below carries through as a
  // constant (each is linear in one token's sources) and which is added back
  // at the end: exact, and ordinary tokens are left untouched.
  double token_log_scale = 0;
  for (size_t i = 0; i < n; ++i) {
    if (u.ids[i] >= 0) continue;
    const double log_bg = std::log(bg_unknown_scale_) + char_log_prob(u.words[i]);
    if (log_bg > kLogTinyToken) continue;
    double hi = log_bg;
    auto for_sources = [&](auto&& f) {
      f(p_you[i]);
      f(p_me[i]);
      f(p_gen[i]);
      f(p_mod[i]);
      for (size_t g = 0; g < G; ++g) f(p_group[g * n + i]);
    };
    for_sources([&](double v) {
      if (v > 0) hi = std::max(hi, std::log(v));
    });
    if (hi == -std::numeric_limits<double>::infinity()) continue;  // no source can emit it
    for_sources([&](double& v) { v = v > 0 ? std::exp(std::log(v) - hi) : 0.0; });
    p_bg[i] = std::exp(log_bg - hi);
    token_log_scale += hi;
  }

  const bool enumerate = G <= static_cast<size_t>(kMaxEnumeratedGroups);
  const uint32_t all = G >= 32 ? ~0u : (1u << G) - 1u;
  const uint32_t first_mask = enumerate ? 0u : all;
  const uint32_t end_mask = enumerate ? all + 1u : all;  // exclusive; non-enumerated: one mask
  const size_t clauses = u.clause_end.size();
  const double log_req = std::log(kRequestClause);
  const double log_stm = std::log(1 - kRequestClause);

  // Mixture of one token under a mask and clause type; also returns, via
  // `den`, each action group's normaliser (1 + weights of its optional units on).
  std::vector<double> den(G, 1.0);
  std::vector<char> on(G, 0);
  auto setup_mask = [&](uint32_t mask, double& log_prior, int& n_you, int& n_me) -> bool {
    log_prior = 0;
    n_you = n_me = 0;
    for (size_t g = 0; g < G; ++g) on[g] = static_cast<char>((mask >> g) & 1u);
    for (size_t g = 0; g < G; ++g) {
      const Bound::Group& grp = c.groups[g];
      if (grp.parent >= 0) {
        const bool parent_on = on[static_cast<size_t>(grp.parent)] != 0;
        if (!parent_on) {
          if (on[g]) return false;  // an optional unit needs its group
          continue;
        }
      }
      if (enumerate) log_prior += on[g] ? grp.log_on : grp.log_off;
    }
    for (size_t g = 0; g < G; ++g) {
      den[g] = 1.0;
      if (c.groups[g].parent < 0 && on[g]) {
        if (in_role(c.groups[g], false)) ++n_you;
        if (in_role(c.groups[g], true)) ++n_me;
      }
    }
    for (size_t g = 0; g < G; ++g) {
      if (c.groups[g].parent >= 0 && on[g]) den[static_cast<size_t>(c.groups[g].parent)] += c.groups[g].unit_weight;
    }
    return true;
  };
  auto content_sum = [&](size_t i, bool speaker) {
    double s = 0;
    for (size_t g = 0; g < G; ++g) {
      const Bound::Group& grp = c.groups[g];
      if (!on[g]) continue;
      const size_t owner = grp.parent >= 0 ? static_cast<size_t>(grp.parent) : g;
      if (!in_role(c.groups[owner], speaker)) continue;
      const double w = grp.parent >= 0 ? grp.unit_weight : 1.0;
      s += w * p_group[g * n + i] / den[owner];
    }
    return s;
  };

  std::vector<double> mix(n * 2);
  // log of the anchored likelihood of the tokens (see below) for the k
  // mentioned action groups K, given the per-token mixtures `mix` and each
  // group's own emission emit(j, i); for a prefix, marginalised over the
  // unseen length (divided by P(N >= n), which the caller adds back).
  auto anchored_log = [&](const size_t* /*K*/, size_t k, const std::vector<double>& mx, auto&& emit) {
    const uint32_t full = (1u << k) - 1u;
    double a[2][1u << kMaxAnchors] = {};
    double b[2][1u << kMaxAnchors];
    double e[1u << kMaxAnchors];
    double single[kMaxAnchors];
    a[0][0] = kRequestClause;
    a[1][0] = 1 - kRequestClause;
    double log_scale = 0;
    size_t clause = 0;
    for (size_t i = 0; i < n; ++i) {
      for (size_t j = 0; j < k; ++j) single[j] = emit(j, i);
      e[0] = 0;
      for (uint32_t S = 1; S <= full; ++S) {
        double v = 0;
        int cnt = 0;
        for (size_t j = 0; j < k; ++j) {
          if ((S >> j) & 1u) {
            v += single[j];
            ++cnt;
          }
        }
        e[S] = v / cnt;
      }
      double zsum = 0;
      for (int t = 0; t < 2; ++t) {
        const double m = mx[2 * i + static_cast<size_t>(t)];
        for (uint32_t A = 0; A <= full; ++A) {
          double anchored = 0;
          for (uint32_t S = A; S != 0; S = (S - 1) & A) anchored += a[t][A ^ S] * e[S];
          const double v = a[t][A] * m + anchored * contra[2 * i + static_cast<size_t>(t)];
          b[t][A] = v;
          zsum += v;
        }
      }
      if (!(zsum > 0)) return -std::numeric_limits<double>::infinity();
      log_scale += std::log(zsum);
      for (int t = 0; t < 2; ++t) {
        for (uint32_t A = 0; A <= full; ++A) a[t][A] = b[t][A] / zsum;
      }
      if (clause < clauses && i + 1 == static_cast<size_t>(u.clause_end[clause])) {
        ++clause;
        if (i + 1 < n) {
          for (uint32_t A = 0; A <= full; ++A) {
            const double sA = a[0][A] + a[1][A];
            a[0][A] = kRequestClause * sA;
            a[1][A] = (1 - kRequestClause) * sA;
          }
        }
      }
    }
    const double kd = static_cast<double>(k);
    if (complete) {
      return log_scale + std::log(a[0][full] + a[1][full]) - kd * std::log(static_cast<double>(n));
    }
    // Prefix: sum over total lengths N >= n of P_len(N) P(prefix | N), where a
    // group's anchor lies in the prefix with probability n / N.
    const std::vector<double>& pmf = length_[static_cast<size_t>(actions_bucket(c.num_actions))];
    double F[1u << kMaxAnchors];
    int pc[1u << kMaxAnchors];
    for (uint32_t A = 0; A <= full; ++A) {
      F[A] = a[0][A] + a[1][A];
      pc[A] = std::popcount(A);
    }
    double s = 0, below = 0;
    const double L = static_cast<double>(n);
    for (size_t N = n; N <= static_cast<size_t>(kMaxLen); ++N) {
      const double Nd = static_cast<double>(N);
      double v = 0;
      for (uint32_t A = 0; A <= full; ++A) {
        v += F[A] * std::pow(Nd, -pc[A]) * std::pow((Nd - L) / Nd, static_cast<double>(k) - pc[A]);
      }
      s += pmf[N] * v;
      below += pmf[N];
    }
    const double tail = std::exp(length_log_prob(c.num_actions, static_cast<int>(n), false));
    const double rest = std::max(0.0, tail - below);
    const double Nt = static_cast<double>(kMaxLen + 1);
    s += rest * F[0] * std::pow((Nt - L) / Nt, kd);
    if (!(s > 0)) return -std::numeric_limits<double>::infinity();
    return log_scale + std::log(s) - std::log(tail);
  };
  std::vector<double> log_m(static_cast<size_t>(end_mask - first_mask) + (enumerate ? 0 : 1),
                            -std::numeric_limits<double>::infinity());
  std::vector<double> clause_log;  // [mask][clause][type] when counting
  if (counts != nullptr) clause_log.resize(log_m.size() * clauses * 2);

  const uint32_t stop = enumerate ? end_mask : first_mask + 1u;
  for (uint32_t mask = first_mask; mask != stop; ++mask) {
    double lp;
    int n_you, n_me;
    if (!setup_mask(mask, lp, n_you, n_me)) continue;
    for (size_t i = 0; i < n; ++i) {
      const double s_you = content_sum(i, false);
      const double s_me = content_sum(i, true);
      const double content_you =
          n_you > 0 ? kGenericShare * p_gen[i] + (1 - kGenericShare) * s_you / n_you : p_gen[i];
      const double content_me =
          n_me > 0 ? kGenericShare * p_gen[i] + (1 - kGenericShare) * s_me / n_me : p_gen[i];
      mix[2 * i] = contra[2 * i] * (kPiBackground * p_bg[i] + kPiAgent * p_you[i] + kPiContent * content_you);
      mix[2 * i + 1] = contra[2 * i + 1] * (kPiBackground * p_bg[i] + kPiAgent * p_me[i] + kPiContent * content_me);
    }
    size_t start = 0;
    for (size_t k = 0; k < clauses; ++k) {
      const size_t end = static_cast<size_t>(u.clause_end[k]);
      double lr = log_req, ls = log_stm;
      double pr = 1, ps = 1;
      for (size_t i = start; i < end; ++i) {
        pr *= mix[2 * i];
        ps *= mix[2 * i + 1];
        // Fold into logs before the running products can underflow.
        if (pr < 1e-200) {
          lr += std::log(pr);
          pr = 1;
        }
        if (ps < 1e-200) {
          ls += std::log(ps);
          ps = 1;
        }
      }
      lr += std::log(pr);
      ls += std::log(ps);
      const double hi = std::max(lr, ls);
      const double lk = hi + std::log(std::exp(lr - hi) + std::exp(ls - hi));
      lp += lk;
      if (counts != nullptr) {
        const size_t base = (static_cast<size_t>(mask - first_mask) * clauses + k) * 2;
        clause_log[base] = lr - lk;
        clause_log[base + 1] = ls - lk;
      }
      start = end;
    }
    // Required mentions: every mentioned action group emits one anchor token,
    // at a position drawn uniformly from the n positions (independently per
    // group); an anchored token is drawn from the anchoring groups' own
    // emissions (uniform mixture when several share it), every other token
    // from the mixture above. Exact sum over anchor placements by a forward
    // pass whose state is the set of groups already anchored.
    if (n > 0) {
      size_t K[kMaxAnchors];
      size_t k = 0;
      for (size_t g = 0; g < G && k < kMaxAnchors; ++g) {
        if (c.groups[g].parent < 0 && on[g]) K[k++] = g;
      }
      if (k > 0) {
        double prior = 0;
        for (size_t g = 0; g < G; ++g) {
          const Bound::Group& grp = c.groups[g];
          if (grp.parent >= 0 && !on[static_cast<size_t>(grp.parent)]) continue;
          if (enumerate) prior += on[g] ? grp.log_on : grp.log_off;
        }
        const double f = anchored_log(K, k, mix, [&](size_t j, size_t i) {
          const size_t g = K[j];
          double v = p_group[g * n + i];
          for (size_t h = 0; h < G; ++h) {
            if (on[h] && c.groups[h].parent == static_cast<int>(g)) v += c.groups[h].unit_weight * p_group[h * n + i];
          }
          return v / den[g];
        });
        lp = prior + f;
      }
    }
    log_m[mask - first_mask] = lp;
  }
  double hi = -std::numeric_limits<double>::infinity();
  for (double v : log_m) hi = std::max(hi, v);
  if (hi == -std::numeric_limits<double>::infinity()) return hi;  // no mention pattern can produce u
  double z = 0;
  for (double v : log_m) z += std::exp(v - hi);
  const double log_words = hi + std::log(z);
  const double total = log_words + token_log_scale + length_log_prob(c.num_actions, static_cast<int>(n), complete);

  if (counts == nullptr) return total;

  // E-step: distribute `weight` over mentions, clause types and sources.
  const size_t bucket = static_cast<size_t>(actions_bucket(c.num_actions));
  if (n <= static_cast<size_t>(kMaxLen)) counts->length[bucket][n] += weight;
  const int id_you = table_ids_.at("A:you");
  const int id_me = table_ids_.at("A:me");
  const int id_gen = table_ids_.at("GEN");
  const int id_mod = table_ids_.at("M");
  for (uint32_t mask = first_mask; mask != stop; ++mask) {
    const double pm = std::exp(log_m[mask - first_mask] - log_words);
    if (!(pm > 1e-9)) continue;
    double lp_unused;
    int n_you, n_me;
    setup_mask(mask, lp_unused, n_you, n_me);
    for (size_t g = 0; g < G && enumerate; ++g) {
      const Bound::Group& grp = c.groups[g];
      if (grp.parent >= 0 && !on[static_cast<size_t>(grp.parent)]) continue;
      counts->mention_all[grp.kind] += weight * pm;
      if (on[g]) counts->mention_on[grp.kind] += weight * pm;
    }
    size_t start = 0;
    for (size_t k = 0; k < clauses; ++k) {
      const size_t end = static_cast<size_t>(u.clause_end[k]);
      for (int t = 0; t < 2; ++t) {
        const bool speaker = t == 1;
        const double pt = std::exp(clause_log[(static_cast<size_t>(mask - first_mask) * clauses + k) * 2 + t]);
        const double wt = weight * pm * pt;
        if (wt < 1e-12) continue;
        const int active = speaker ? n_me : n_you;
        for (size_t i = start; i < end; ++i) {
          const int id = u.ids[i];
          if (id < 0) continue;  // training tokens are always in the vocabulary
          const double p_agent = speaker ? p_me[i] : p_you[i];
          const double gen_share = active > 0 ? kGenericShare : 1.0;
          const double content =
              gen_share * p_gen[i] + (active > 0 ? (1 - kGenericShare) * content_sum(i, speaker) / active : 0.0);
          const double m = kPiBackground * p_bg[i] + kPiAgent * p_agent + kPiContent * content;
          if (m <= 0) continue;
          const double r = wt / m;
          const size_t uid = static_cast<size_t>(id);
          counts->bg[uid] += r * kPiBackground * p_bg[i];
          counts->table[static_cast<size_t>(speaker ? id_me : id_you)][uid] += r * kPiAgent * p_agent;
          counts->table[static_cast<size_t>(id_gen)][uid] += r * kPiContent * gen_share * p_gen[i];
          if (active == 0) continue;
          const double share = r * kPiContent * (1 - kGenericShare) / active;
          for (size_t g = 0; g < G; ++g) {
            const Bound::Group& grp = c.groups[g];
            if (!on[g]) continue;
            const size_t owner = grp.parent >= 0 ? static_cast<size_t>(grp.parent) : g;
            if (!in_role(c.groups[owner], speaker)) continue;
            const double unit = share * (grp.parent >= 0 ? grp.unit_weight : 1.0) / den[owner];
            const bool in_mod = have_spans && u.in_modifier[i] != 0 && grp.kind == 0;
            if (in_mod) counts->table[static_cast<size_t>(id_mod)][uid] += unit * grp.nonverb_weight * p_mod[i];
            for (const Bound::Field& f : grp.fields) {
              if (in_mod && !f.verb) continue;
              const double e = unit * f.weight * f.table->at(id, u.words[i]);
              if (f.table_index >= 0) counts->table[static_cast<size_t>(f.table_index)][uid] += e;
              if (f.residual) counts->non_copy += e;
            }
            for (const Bound::Copy& cp : grp.copies) {
              if (id == cp.id) counts->copy += unit * cp.weight * bind_factor(grp, i);
            }
          }
        }
      }
      start = end;
    }
  }
  return total;
}

double AlignmentModel::log_prob(const Bound& c, const EncodedUtterance& u, bool complete) const {
  return evaluate(c, u, complete, nullptr, 0.0);
}

double AlignmentModel::length_mass(int actions, int max_n) const {
  double s = 0;
  for (int k = 0; k <= max_n; ++k) s += std::exp(length_log_prob(actions, k, true));
  return s;
}

double AlignmentModel::next_token_mass(const std::string& command, bool mentioned_all,
                                       bool request_clause) const {
  auto c = bind(command);
  auto table_mass = [](const Table& t) {
    double s = 0;
    for (double p : t.prob) s += p;
    for (const auto& [w, p] : t.extra) s += p;
    return s;
  };
  double bg = 0, chars_in_vocab = 0;
  for (size_t i = 0; i < words_.size(); ++i) {
    bg += bg_[i];
    chars_in_vocab += char_prob(words_[i]);
  }
  bg += bg_unknown_scale_ * (1 - chars_in_vocab);
  const Table& agent = *tables_[static_cast<size_t>(table_ids_.at(request_clause ? "A:you" : "A:me"))];
  const double gen = table_mass(*tables_[static_cast<size_t>(table_ids_.at("GEN"))]);
  double groups = 0;
  int active = 0;
  for (const Bound::Group& g : c->groups) {
    const Bound::Group& owner = g.parent >= 0 ? c->groups[static_cast<size_t>(g.parent)] : g;
    if (!mentioned_all || owner.speaker == request_clause) continue;
    double den = 1;
    for (const Bound::Group& h : c->groups) {
      if (&c->groups[static_cast<size_t>(std::max(h.parent, 0))] == &owner && h.parent >= 0) den += h.unit_weight;
    }
    const double w = (g.parent >= 0 ? g.unit_weight : 1.0) / den;
    if (g.parent < 0) ++active;
    for (const Bound::Field& f : g.fields) groups += w * f.weight * table_mass(*f.table);
    for (const Bound::Copy& cp : g.copies) groups += w * cp.weight;
  }
  const double content = active > 0 ? kGenericShare * gen + (1 - kGenericShare) * groups / active : gen;
  return kPiBackground * bg + kPiAgent * table_mass(agent) + kPiContent * content;
}

std::string AlignmentModel::explain(const std::string& command, const std::string& utterance) const {
  auto c = bind(command);
  EncodedUtterance u = encode(utterance);
  const Table& a_you = *tables_[static_cast<size_t>(table_ids_.at("A:you"))];
  const Table& a_me = *tables_[static_cast<size_t>(table_ids_.at("A:me"))];
  const Table& gen = *tables_[static_cast<size_t>(table_ids_.at("GEN"))];
  const Table& mod = *tables_[static_cast<size_t>(table_ids_.at("M"))];
  std::string out = "alpha=" + std::to_string(copy_alpha_) + " rho_group=" + std::to_string(mention_[0]) +
                    " rho_recipient=" + std::to_string(mention_[1]) +
                    " rho_attribute=" + std::to_string(mention_[2]) +
                    " log_len=" + std::to_string(length_log_prob(c->num_actions, static_cast<int>(u.words.size()), true)) +
                    "\n";
  for (size_t i = 0; i < u.words.size(); ++i) {
    const int id = u.ids[i];
    const std::string& w = u.words[i];
    char buf[256];
    const bool in_mod = u.in_modifier[i] != 0;
    std::snprintf(buf, sizeof buf, "%-12s%s bg=%.4f you=%.4f me=%.4f gen=%.4f", w.c_str(), in_mod ? "[mod]" : "",
                  bg_prob(id, w), a_you.at(id, w), a_me.at(id, w), gen.at(id, w));
    out += buf;
    if (in_mod) {
      std::snprintf(buf, sizeof buf, " M=%.4f", mod.at(id, w));
      out += buf;
    }
    for (const Bound::Group& g : c->groups) {
      out += " |";
      for (const Bound::Field& f : g.fields) {
        std::snprintf(buf, sizeof buf, " %s=%.4f", f.table->key.c_str(), f.table->at(id, w));
        out += buf;
      }
      for (const Bound::Copy& cp : g.copies) {
        if (id >= 0 ? id == cp.id : w == cp.word) out += " copy";
      }
    }
    out += "\n";
  }
  return out;
}

// ------------------------------------------------------------------------------------

struct Trainer {
  static std::shared_ptr<AlignmentModel> run(const std::vector<TrainingPair>& pairs, int iterations) {
    std::shared_ptr<AlignmentModel> m(new AlignmentModel());
    AlignmentModel& M = *m;

    // Parse everything first so malformed input fails before any work.
    std::vector<CommandFrame> frames;
    std::vector<std::vector<std::string>> tokens;
    for (const TrainingPair& p : pairs) {
      frames.push_back(parse_command_frame(p.command, p.origin));
      tokens.push_back(tokenize_utterance(p.utterance));
    }

    // Vocabulary: punctuation first (always present), training tokens, base words.
    for (const char* punct : {",", ".", "?", "!"}) M.add_word(punct);
    for (const auto& t : tokens) {
      for (const std::string& w : t) M.add_word(w);
    }
    std::set<std::string> keys = {"A:you", "A:me", "P:me"};
    std::set<std::string> attributes;
    for (const CommandFrame& f : frames) {
      for (const FrameGroup& g : f.groups) {
        keys.insert(verb_key(g));
        if (!g.type.empty()) keys.insert(noun_key(g));
        if (g.count >= 2) keys.insert(number_key(g.count));
        for (const std::string& a : g.attributes) attributes.insert(a);
      }
    }
    std::map<std::string, WordDistribution> bases;
    for (const std::string& k : keys) {
      bases[k] = base_for_key(k);
      for (const auto& [w, p] : bases[k]) M.add_word(w);
    }
    for (const std::string& a : attributes) M.add_word(a);
    const size_t V = M.words_.size();

    // GEN: domain content words in general. R: what an attribute field says when
    // it does not copy its value (e.g. "coloured", another attribute word).
    WordDistribution gen_base;
    {
      std::map<std::string, double> acc;
      double parts = 0;
      for (const auto& [k, d] : bases) {
        if (k[0] != 'V' && k[0] != 'N') continue;
        parts += 1;
        for (const auto& [w, p] : d) {
          if (!is_function_word(w)) acc[w] += p;
        }
      }
      for (const std::string& a : attributes) acc[a] += parts / 4.0 / std::max<double>(1, attributes.size());
      double z = 0;
      for (auto& [w, p] : acc) z += p;
      for (auto& [w, p] : acc) gen_base.emplace_back(w, p / z);
    }
    WordDistribution residual_base;
    for (const std::string& a : attributes) residual_base.emplace_back(a, 1.0);
    residual_base.emplace_back("colored", 1.0);
    residual_base.emplace_back("coloured", 1.0);
    residual_base.emplace_back("color", 1.0);
    residual_base.emplace_back("colour", 1.0);
    for (auto& [w, p] : residual_base) {
      M.add_word(w);
      p /= static_cast<double>(residual_base.size());
    }
    bases["GEN"] = gen_base;
    bases["M"] = gen_base;  // modifier heads: domain nouns ("door", "table"), learned by EM
    bases["R"] = residual_base;
    const size_t V2 = M.words_.size();
    (void)V;

    // Character bigram model over the vocabulary's word types (add-1/2 smoothing).
    {
      std::vector<double> first(kCharSymbols, 0.5);
      std::vector<double> next(static_cast<size_t>(kCharSymbols * (kCharSymbols + 1)), 0.5);
      for (const std::string& w : M.words_) {
        int prev = -1;
        bool ok = !w.empty();
        for (char ch : w) ok = ok && char_index(ch) >= 0;
        if (!ok) continue;
        for (char ch : w) {
          const int c = char_index(ch);
          if (prev < 0) {
            first[static_cast<size_t>(c)] += 1;
          } else {
            next[static_cast<size_t>(prev * (kCharSymbols + 1) + c)] += 1;
          }
          prev = c;
        }
        next[static_cast<size_t>(prev * (kCharSymbols + 1) + kCharSymbols)] += 1;
      }
      double z = 0;
      for (double v : first) z += v;
      for (double& v : first) v /= z;
      for (int p = 0; p < kCharSymbols; ++p) {
        double s = 0;
        for (int c = 0; c <= kCharSymbols; ++c) s += next[static_cast<size_t>(p * (kCharSymbols + 1) + c)];
        for (int c = 0; c <= kCharSymbols; ++c) next[static_cast<size_t>(p * (kCharSymbols + 1) + c)] /= s;
      }
      M.char_first_ = std::move(first);
      M.char_next_ = std::move(next);
    }
    std::vector<double> char_in_vocab(V2);
    for (size_t i = 0; i < V2; ++i) char_in_vocab[i] = M.char_prob(M.words_[i]);

    // Tables. The prior base of a table is its lexical base mixed with a small
    // uniform floor over the words its kind may emit (content words for content
    // fields, closed-class words for the speech-act sources), so EM can discover
    // words the lexicon lacks (WordNet has no grab -> pick up). The first E-step
    // uses a much larger floor, the usual uniform start of alignment models, so
    // that co-occurrence decides the first responsibilities.
    // Verb fields may only learn verb-like words and noun fields noun-like ones:
    // otherwise a noun field shared by several actions (N:key) soaks up their
    // verbs ("grab") and the verb fields stop telling actions apart. Nor do
    // noun fields learn places ("kitchen", "cupboard") beyond their lexical
    // base: from "kitchen knife" the chef's knife table would otherwise take
    // "kitchen", and "the wine is in the kitchen" would ask for a knife.
    std::vector<int> content_ids, function_ids, noun_ids, verb_ids;
    for (size_t i = 0; i < V2; ++i) {
      const std::string& w = M.words_[i];
      if (is_function_word(w)) {
        function_ids.push_back(static_cast<int>(i));
        continue;
      }
      content_ids.push_back(static_cast<int>(i));
      if (is_punctuation_token(w)) continue;
      const WordNetLexicon::WordClass wc = WordNetLexicon::instance().word_class(w);
      if (wc.noun_like && !WordNetLexicon::instance().names_place(w)) noun_ids.push_back(static_cast<int>(i));
      if (wc.verb_like) verb_ids.push_back(static_cast<int>(i));
    }
    // Word classes for reading noun phrases (AlignmentModel::mark_modifiers).
    // Attribute values (colours, also as residual words) are pure modifiers.
    std::set<std::string> modifier_words(attributes.begin(), attributes.end());
    for (const auto& [w, p] : residual_base) modifier_words.insert(w);
    M.word_flags_.assign(V2, 0);
    M.attribute_word_.assign(V2, 0);
    for (const std::string& a : attributes) M.attribute_word_[static_cast<size_t>(M.word_ids_.at(a))] = 1;
    for (size_t i = 0; i < V2; ++i) {
      const std::string& w = M.words_[i];
      uint8_t f = closed_class_flags(w);
      if ((f & kWordFunction) == 0 && !is_punctuation_token(w)) {
        if (modifier_words.count(w) != 0) {
          f |= kWordModifier;
        } else {
          const WordNetLexicon::WordClass wc = WordNetLexicon::instance().word_class(w);
          if (wc.noun_like) f |= kWordNoun;
          if (wc.verb_like) f |= kWordVerb;
          if (wc.adjective_like) f |= kWordModifier;
        }
      }
      M.word_flags_[i] = f;
    }
    auto with_floor = [&](const WordDistribution& d, const std::vector<int>& floor_ids, double eps) {
      std::vector<std::pair<int, double>> out;
      for (const auto& [w, p] : d) out.emplace_back(M.word_ids_.at(w), (1 - eps) * p);
      for (int id : floor_ids) out.emplace_back(id, eps / static_cast<double>(floor_ids.size()));
      if (floor_ids.empty()) {
        for (auto& [id, p] : out) p /= 1 - eps;
      }
      return out;
    };
    for (const auto& [k, d] : bases) {
      const int ti = M.table_index(k);
      AlignmentModel::Table& t = *M.tables_[static_cast<size_t>(ti)];
      const bool agent = k[0] == 'A' || k[0] == 'P';
      t.kappa = agent ? kKappaAgent : (k == "GEN" || k == "M") ? kKappaGeneric : kKappaContent;
      // The recipient unit is a closed set of words ("me", "my way", "here").
      static const std::vector<int> no_floor;
      const std::vector<int>& floor_ids = k[0] == 'P'   ? no_floor
                                          : agent       ? function_ids
                                          : k[0] == 'N' ? noun_ids
                                          : k[0] == 'V' ? verb_ids
                                                        : content_ids;
      t.base = with_floor(d, floor_ids, kBaseFloor);
      t.prob.assign(V2, 0.0);
      // GEN starts flat: it must not out-compete the command's own fields for
      // the words they co-occur with before EM has seen the data.
      const double init_floor = (k == "GEN" || k == "M") ? 0.95 : kInitialFloor;
      for (const auto& [id, p] : with_floor(d, floor_ids, init_floor)) t.prob[static_cast<size_t>(id)] += p;
    }

    // Relative frequencies of the training tokens.
    std::vector<double> unigram(V2, 0.0);
    {
      double total = 0;
      for (size_t p = 0; p < pairs.size(); ++p)
        for (const std::string& w : tokens[p]) {
          unigram[static_cast<size_t>(M.word_ids_.at(w))] += pairs[p].weight;
          total += pairs[p].weight;
        }
      if (total > 0)
        for (double& u : unigram) u /= total;
    }
    // Background initialised to smoothed relative frequencies of all tokens.
    // A share of it stays on the plain token frequencies: a word that EM hands
    // entirely to some command field ("short" to one noun, "more" to a number)
    // keeps a little background mass, so in an utterance about something else
    // it is not evidence for whichever command happens to own it.
    auto set_background = [&](const std::vector<double>& cnt) {
      double total = 0;
      for (double v : cnt) total += v;
      M.bg_.assign(V2, 0.0);
      for (size_t i = 0; i < V2; ++i) {
        M.bg_[i] = (1 - kUnigramShare) * (cnt[i] + kKappaBackground * char_in_vocab[i]) / (total + kKappaBackground) +
                   kUnigramShare * unigram[i];
      }
      M.bg_unknown_scale_ = (1 - kUnigramShare) * kKappaBackground / (total + kKappaBackground);
      // Mix in the novel-word share: with it every word gets at least
      // kNovelWordShare times its spelled-out probability.
      for (size_t i = 0; i < V2; ++i) M.bg_[i] = (1 - kNovelWordShare) * M.bg_[i] + kNovelWordShare * char_in_vocab[i];
      M.bg_unknown_scale_ = (1 - kNovelWordShare) * M.bg_unknown_scale_ + kNovelWordShare;
    };
    std::vector<double> punct_pseudo(V2, 0.0);
    for (int i = 0; i < 4; ++i) punct_pseudo[static_cast<size_t>(i)] = 0.5;
    {
      std::vector<double> cnt = punct_pseudo;
      for (size_t p = 0; p < pairs.size(); ++p) {
        // Content words start with a tenth of their frequency so the first
        // E-step credits them to the command's fields where those fit.
        for (const std::string& w : tokens[p]) {
          cnt[static_cast<size_t>(M.word_ids_.at(w))] += pairs[p].weight * (is_function_word(w) ? 1.0 : 0.1);
        }
      }
      set_background(cnt);
    }

    // Length model placeholder (uniform-ish) for the E-steps; refit each M-step.
    M.length_.assign(kMaxActionsBucket + 1, std::vector<double>(kMaxLen + 1, 0.0));
    M.length_tail_scale_.assign(kMaxActionsBucket + 1, 1.0);
    M.length_mean_.assign(kMaxActionsBucket + 1, 8.0);
    for (auto& row : M.length_) {
      for (int k = 0; k <= kMaxLen; ++k) row[static_cast<size_t>(k)] = length_base(k, 8.0);
    }

    std::vector<EncodedUtterance> encoded;
    for (const TrainingPair& p : pairs) encoded.push_back(M.encode(p.utterance));

    for (int it = 0; it < std::max(1, iterations); ++it) {
      AlignmentModel::Counts counts;
      counts.table.assign(M.tables_.size(), std::vector<double>(V2, 0.0));
      counts.bg = punct_pseudo;
      counts.length.assign(kMaxActionsBucket + 1, std::vector<double>(kMaxLen + 1, 0.0));
      for (size_t p = 0; p < pairs.size(); ++p) {
        auto b = M.bind(pairs[p].command);
        M.evaluate(*b, encoded[p], true, &counts, pairs[p].weight);
      }
      // M-step.
      for (size_t ti = 0; ti < M.tables_.size(); ++ti) {
        AlignmentModel::Table& t = *M.tables_[ti];
        std::vector<double>& cnt = counts.table[ti];
        // Content fields keep closed-class words at zero unless the base has them;
        // EM cannot move mass there anyway (their probability starts at zero).
        double total = 0;
        for (double v : cnt) total += v;
        t.prob.assign(V2, 0.0);
        for (size_t w = 0; w < V2; ++w) t.prob[w] = cnt[w] / (total + t.kappa);
        for (const auto& [id, p] : t.base) t.prob[static_cast<size_t>(id)] += t.kappa * p / (total + t.kappa);
      }
      set_background(counts.bg);
      for (int kind = 0; kind < 3; ++kind) {
        M.mention_[kind] = (counts.mention_on[kind] + 2 * kMention) / (counts.mention_all[kind] + 2);
        M.mention_[kind] = std::clamp(M.mention_[kind], 0.05, 0.95);
      }
      M.copy_alpha_ = (counts.copy + kAlphaPriorCopy) /
                      (counts.copy + counts.non_copy + kAlphaPriorCopy + kAlphaPriorOther);
      fit_length(M, counts.length);
    }
    return m;
  }

  // A length histogram with every long observation spread over nearby lengths
  // (triangular, half-width a fifth of the length; kept inside 0..kMaxLen), so
  // that one long training utterance does not make its exact length several
  // nats likelier than its neighbours. Short lengths are dense in training and
  // stay as counted. Total mass is kept.
  static std::vector<double> spread_lengths(const std::vector<double>& cnt) {
    std::vector<double> out(cnt.size(), 0.0);
    const int last = static_cast<int>(cnt.size()) - 1;
    for (int k = 0; k <= last; ++k) {
      const double c = cnt[static_cast<size_t>(k)];
      if (c <= 0) continue;
      if (k < kLengthSpreadFrom) {
        out[static_cast<size_t>(k)] += c;
        continue;
      }
      const int w = std::max(1, static_cast<int>(std::lround(kLengthSpread * k)));
      double z = 0;
      for (int d = -w; d <= w; ++d)
        if (k + d >= 0 && k + d <= last) z += w + 1 - std::abs(d);
      for (int d = -w; d <= w; ++d)
        if (k + d >= 0 && k + d <= last) out[static_cast<size_t>(k + d)] += c * (w + 1 - std::abs(d)) / z;
    }
    return out;
  }

  static void fit_length(AlignmentModel& M, const std::vector<std::vector<double>>& cnt) {
    // Mean length per action bucket, borrowing from neighbours when a bucket is empty.
    double all_n = 0, all_sum = 0;
    for (const auto& row : cnt) {
      for (int k = 0; k <= kMaxLen; ++k) {
        all_n += row[static_cast<size_t>(k)];
        all_sum += k * row[static_cast<size_t>(k)];
      }
    }
    const double overall = all_n > 0 ? all_sum / all_n : 8.0;
    for (size_t a = 0; a < cnt.size(); ++a) {
      double n = 0, s = 0;
      for (int k = 0; k <= kMaxLen; ++k) {
        n += cnt[a][static_cast<size_t>(k)];
        s += k * cnt[a][static_cast<size_t>(k)];
      }
      const double prior_mean = overall + 2.0 * (static_cast<double>(a) - 1.5);
      const double mean = std::max(2.0, (s + 3.0 * prior_mean) / (n + 3.0));
      M.length_mean_[a] = mean;
      // The base keeps at least kLengthBaseShare in every bucket, so beyond the
      // lengths seen in training all buckets have about the same tail: a long,
      // padded utterance says little about how many actions a command has, and
      // with a count-dependent share (kappa / (n + kappa)) the tail would be
      // thinnest for the commands the corpus happens to hold most of.
      const double base_share = std::max(kLengthBaseShare, kKappaLength / (n + kKappaLength));
      const std::vector<double> smooth = spread_lengths(cnt[a]);
      M.length_tail_scale_[a] = base_share;
      for (int k = 0; k <= kMaxLen; ++k) {
        const double seen = n > 0 ? smooth[static_cast<size_t>(k)] / n : 0.0;
        M.length_[a][static_cast<size_t>(k)] =
            (n > 0 ? (1 - base_share) * seen : 0.0) + (n > 0 ? base_share : 1.0) * length_base(k, mean);
      }
    }
  }
};

std::shared_ptr<AlignmentModel> AlignmentModel::train(const std::vector<TrainingPair>& pairs, int iterations) {
  auto m = Trainer::run(pairs, iterations);
  // Mass of the closed-class words and punctuation, for log_prob_unprimed.
  double closed = 0;
  for (size_t id = 0; id < m->words_.size() && id < m->bg_.size() && id < m->word_flags_.size(); ++id) {
    const uint8_t f = m->word_flags_[id];
    const bool punct = !m->words_[id].empty() && char_index(m->words_[id][0]) < 0 &&
                       !(f & (kWordNoun | kWordVerb | kWordModifier));
    if ((f & kWordFunction) || punct) closed += m->bg_[id];
  }
  m->closed_mass_ = closed;
  return m;
}

// ---- snapshot ------------------------------------------------------------------

namespace {

constexpr char kSnapshotMagic[8] = {'C', 'L', 'I', 'P', 'S', 'A', 'M', '2'};

// FNV-1a over the payload, stored last: a snapshot damaged on disk (a flipped
// bit in a probability) is rejected instead of scoring silently wrong.
uint64_t snapshot_checksum(std::string_view payload) { return util::fnv1a64(payload); }

struct Writer {
  std::string out;
  template <class T>
  void pod(const T& v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void size(size_t n) { pod(static_cast<uint64_t>(n)); }
  void str(const std::string& x) {
    size(x.size());
    out += x;
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    size(v.size());
    if (!v.empty()) out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
};

struct Reader {
  std::string_view in;  // the payload, without the trailing checksum
  size_t at = 0;
  void need(size_t n) const {
    if (n > in.size() - at) throw LmError("embedded LM snapshot: truncated at byte " + std::to_string(at));
  }
  template <class T>
  T pod() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, in.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
  }
  size_t size() {
    const uint64_t n = pod<uint64_t>();
    // No field is longer than the snapshot itself.
    if (n > in.size()) throw LmError("embedded LM snapshot: implausible length at byte " + std::to_string(at - 8));
    return static_cast<size_t>(n);
  }
  std::string str() {
    const size_t n = size();
    need(n);
    std::string x(in.substr(at, n));
    at += n;
    return x;
  }
  template <class T>
  std::vector<T> vec() {
    const size_t n = size();
    need(n * sizeof(T));
    std::vector<T> v(n);
    if (n != 0) std::memcpy(v.data(), in.data() + at, n * sizeof(T));
    at += n * sizeof(T);
    return v;
  }
};

}  // namespace

std::string AlignmentModel::save() const {
  Writer w;
  w.out.append(kSnapshotMagic, sizeof(kSnapshotMagic));
  w.size(words_.size());
  for (const std::string& x : words_) w.str(x);
  w.vec(word_flags_);
  w.vec(attribute_word_);
  w.vec(char_first_);
  w.vec(char_next_);
  w.vec(bg_);
  w.pod(bg_unknown_scale_);
  w.pod(closed_mass_);
  w.size(tables_.size());
  for (const auto& t : tables_) {
    w.str(t->key);
    w.vec(t->prob);
    w.size(t->base.size());  // field by field: a pair has padding bytes
    for (const auto& [id, p] : t->base) {
      w.pod(id);
      w.pod(p);
    }
    w.pod(t->kappa);
  }
  w.pod(copy_alpha_);
  for (double m : mention_) w.pod(m);
  w.size(length_.size());
  for (const auto& row : length_) w.vec(row);
  w.vec(length_tail_scale_);
  w.vec(length_mean_);
  w.pod(snapshot_checksum(w.out));
  return std::move(w.out);
}

std::shared_ptr<AlignmentModel> AlignmentModel::load(const std::string& bytes) {
  if (bytes.size() < sizeof(kSnapshotMagic) + sizeof(uint64_t) ||
      std::memcmp(bytes.data(), kSnapshotMagic, sizeof(kSnapshotMagic)) != 0)
    throw LmError("embedded LM snapshot: not a snapshot of this format");
  const size_t payload = bytes.size() - sizeof(uint64_t);
  uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + payload, sizeof(stored));
  const std::string_view body(bytes.data(), payload);
  if (stored != snapshot_checksum(body)) throw LmError("embedded LM snapshot: checksum mismatch");
  Reader r{body, sizeof(kSnapshotMagic)};
  std::shared_ptr<AlignmentModel> m(new AlignmentModel());
  const size_t V = r.size();
  for (size_t i = 0; i < V; ++i) m->add_word(r.str());
  if (m->words_.size() != V) throw LmError("embedded LM snapshot: repeated vocabulary word");
  m->word_flags_ = r.vec<uint8_t>();
  m->attribute_word_ = r.vec<char>();
  m->char_first_ = r.vec<double>();
  m->char_next_ = r.vec<double>();
  m->bg_ = r.vec<double>();
  m->bg_unknown_scale_ = r.pod<double>();
  m->closed_mass_ = r.pod<double>();
  const size_t nt = r.size();
  for (size_t i = 0; i < nt; ++i) {
    Table& t = *m->tables_[static_cast<size_t>(m->table_index(r.str()))];
    t.prob = r.vec<double>();
    const size_t nb = r.size();
    for (size_t j = 0; j < nb; ++j) {
      const int id = r.pod<int>();
      t.base.emplace_back(id, r.pod<double>());
    }
    t.kappa = r.pod<double>();
    if (t.prob.size() != V) throw LmError("embedded LM snapshot: table '" + t.key + "' does not cover the vocabulary");
    for (const auto& [id, p] : t.base)
      if (id < 0 || static_cast<size_t>(id) >= V) throw LmError("embedded LM snapshot: table '" + t.key + "' has a bad word id");
  }
  if (m->tables_.size() != nt) throw LmError("embedded LM snapshot: repeated table key");
  m->copy_alpha_ = r.pod<double>();
  for (double& x : m->mention_) x = r.pod<double>();
  const size_t nl = r.size();
  for (size_t i = 0; i < nl; ++i) m->length_.push_back(r.vec<double>());
  m->length_tail_scale_ = r.vec<double>();
  m->length_mean_ = r.vec<double>();
  const bool shapes_ok = m->word_flags_.size() == V && m->attribute_word_.size() == V && m->bg_.size() == V &&
                         m->char_first_.size() == static_cast<size_t>(kCharSymbols) &&
                         m->char_next_.size() == static_cast<size_t>(kCharSymbols * (kCharSymbols + 1)) &&
                         m->length_.size() == static_cast<size_t>(kMaxActionsBucket + 1) &&
                         m->length_tail_scale_.size() == m->length_.size() && m->length_mean_.size() == m->length_.size();
  if (!shapes_ok) throw LmError("embedded LM snapshot: arrays of the wrong shape");
  for (const auto& row : m->length_)
    if (row.size() != static_cast<size_t>(kMaxLen + 1)) throw LmError("embedded LM snapshot: arrays of the wrong shape");
  if (r.at != body.size()) throw LmError("embedded LM snapshot: trailing bytes");
  return m;
}

}  // namespace clips::lm
