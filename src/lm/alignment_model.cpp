#include "lm/alignment_model.hpp"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cmath>
#include <limits>
#include <mutex>
#include <string_view>
#include <unordered_set>

#include "lm/alignment_internal.hpp"
#include "lm/utterance_tokens.hpp"
#include "lm/wordnet_lexicon.hpp"

namespace clips::lm {

namespace {

double log_poisson(int n, double mu) {
  return n * std::log(mu) - mu - std::lgamma(n + 1.0);
}

}  // namespace

// Base distribution of lengths: mostly Poisson around the mean, with a
// geometric component so long utterances are never impossible.
double length_base(int n, double mean) {
  const double p = 1.0 / 16.0;
  return 0.8 * std::exp(log_poisson(n, mean)) + 0.2 * p * std::pow(1 - p, n);
}

namespace {

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

}  // namespace

std::string verb_key(const FrameGroup& g) {
  return "V:" + g.action + "/" + g.agent + (g.to_speaker ? "/to-me" : "");
}
std::string noun_key(const FrameGroup& g) {
  return "N:" + g.type + (g.count >= 2 ? "/pl" : "/sg");
}
std::string number_key(int count) { return "Q:" + std::to_string(std::min(count, 10)); }

// Lexical base of a table key (the keys above plus the fixed sources).
WordDistribution base_for_key(const std::string& key, const NounSenses& senses) {
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
  if (key.rfind("F:", 0) == 0) return WordNetLexicon::instance().function_words(key.substr(2));
  if (key.rfind("N:", 0) == 0) {
    const size_t slash = key.rfind('/');
    const std::string type = key.substr(2, slash - 2);
    const auto sense = senses.find(type);
    return WordNetLexicon::instance().noun_base(type, key.substr(slash) == "/pl",
                                                sense == senses.end() ? 0 : sense->second);
  }
  return {};  // GEN and R get their bases from the trainer
}

// ------------------------------------------------------------------------------------

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
  const bool function_table = key.rfind("F:", 0) == 0;
  for (const auto& [w, p] : base_for_key(key, noun_senses_)) {
    auto it = word_ids_.find(w);
    // What a thing is for is not one of the domain's qualifier values
    // ("plastic" in a beaker's gloss is not its use).
    if (function_table && it != word_ids_.end() && attribute_word_[static_cast<size_t>(it->second)]) continue;
    if (it != word_ids_.end()) {
      t->prob[static_cast<size_t>(it->second)] += p;
    } else {
      t->extra[w] += p;
    }
  }
  if (function_table) {  // renormalised over the words kept (possibly none)
    double total = 0;
    for (double p : t->prob) total += p;
    for (const auto& [w, p] : t->extra) total += p;
    if (total > 0) {
      for (double& p : t->prob) p /= total;
      for (auto& [w, p] : t->extra) p /= total;
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
    // What the object is for ("something to dig with"), where it is known.
    const Table* use = function_words_ && !g.type.empty() ? find_or_make_table("F:" + g.type) : nullptr;
    if (use != nullptr && std::all_of(use->prob.begin(), use->prob.end(), [](double p) { return p <= 0; }) &&
        use->extra.empty())
      use = nullptr;
    const double z = kWeightVerb + (g.type.empty() ? 0 : kWeightNoun) + (g.count >= 2 ? kWeightNumber : 0) +
                     (use != nullptr ? kWeightFunction : 0);
    bg.fields.push_back(field_of(verb_key(g), kWeightVerb / z));
    bg.fields.back().verb = true;
    if (!g.type.empty()) bg.fields.push_back(field_of(noun_key(g), kWeightNoun / z));
    if (use != nullptr) {
      // Kept inside modifier spans like a verb: "a tool for driving nails".
      bg.fields.push_back(Bound::Field{use, -1, kWeightFunction / z, false});
      bg.fields.back().verb = true;
    }
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
    // The number of a numbered place ("shelf 3"): a unit of its own, as
    // heavy as one attribute, with its own mention rate (most places are
    // named without one).
    for (const std::string& num : g.numbers) {
      Bound::Group nu;
      nu.speaker = b->groups[static_cast<size_t>(parent)].speaker;
      nu.kind = 3;
      nu.parent = parent;
      nu.unit_weight = kWeightAttribute / z / static_cast<double>(std::max<size_t>(1, g.attributes.size()));
      nu.log_on = std::log(mention_[3]);
      nu.log_off = std::log(1 - mention_[3]);
      auto it = word_ids_.find(num);
      nu.copies.push_back(Bound::Copy{it == word_ids_.end() ? -1 : it->second, num, copy_alpha_});
      nu.fields.push_back(Bound::Field{residual, residual_index, 1 - copy_alpha_, true});
      b->groups.push_back(std::move(nu));
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

namespace {

// The action groups a clause of each type talks about (header, item 4): a
// request those of the listener; a statement the speaker's own, and what
// is handed to the speaker ("I'm in need of the blue key").
bool in_role(const AlignmentModel::Bound::Group& grp, bool statement) {
  return statement ? grp.speaker || grp.to_speaker : !grp.speaker;
}

}  // namespace

// The largest mass any trained noun table gives a word: whether it names a type.
double AlignmentModel::best_noun_mass(int id, const std::string& w) const {
  double best = 0;
  for (int t : noun_tables_) best = std::max(best, tables_[static_cast<size_t>(t)]->at(id, w));
  return best;
}

// Colour binding (header, item 6): the share of its copy weight that
// group g of c (an attribute unit, or a number field's group) keeps at token i.
double AlignmentModel::colour_binding(const Bound& c, size_t g, const EncodedUtterance& u, size_t i) const {
  const Bound::Group& grp = c.groups[g];
  const bool have_heads = u.noun_heads.size() == u.ids.size();
  if (!have_heads || grp.type_nouns[0] == nullptr) return 1.0;
  bool typed = false;
  for (int j : u.noun_heads[i]) {
    if (j < 0) continue;
    const int hid = u.ids[static_cast<size_t>(j)];
    const std::string& hw = u.words[static_cast<size_t>(j)];
    const double best = best_noun_mass(hid, hw);
    if (best < kTypedNoun) return 1.0;  // "one", "thing": says nothing about the type
    typed = true;
    const double own = std::max(grp.type_nouns[0]->at(hid, hw), grp.type_nouns[1]->at(hid, hw));
    if (own >= kBindRatio * best) return 1.0;
  }
  return typed ? kMisboundCopy : 1.0;
}

// The qualifier predicates (bits of attribute_word_) an attribute unit's value
// belongs to; a value the vocabulary lacks may be of any kind.
unsigned AlignmentModel::qualifier_kinds(const Bound& c, size_t unit) const {
  unsigned kinds = 0;
  for (const Bound::Copy& cp : c.groups[unit].copies) {
    if (cp.id < 0 || static_cast<size_t>(cp.id) >= attribute_word_.size()) return 0xFFu;
    kinds |= static_cast<unsigned char>(attribute_word_[static_cast<size_t>(cp.id)]);
  }
  return kinds == 0 ? 0xFFu : kinds;
}

// Contradicted colours (header, item 7): contra[2 * i + t] is the factor on
// token i in a clause of type t (0: request, groups of "you"; 1: statement,
// groups of "me").
std::vector<double> AlignmentModel::colour_contradictions(const Bound& c, const EncodedUtterance& u) const {
  const size_t n = u.ids.size();
  const size_t G = c.groups.size();
  const bool have_heads = u.noun_heads.size() == n;
  std::vector<double> contra(2 * n, 1.0);
  // Whether action group g's object may have the value `id` of a qualifier
  // of the kinds `token_kinds`: it has that value, or no known value of those
  // kinds ("wooden" says nothing against a known size; a colourless object
  // may be any colour).
  auto may_be = [&](size_t g, int id, unsigned token_kinds) {
    bool valued = false;
    for (size_t k = 0; k < G; ++k) {
      const Bound::Group& unit = c.groups[k];
      if (unit.parent != static_cast<int>(g) || unit.kind != 2) continue;
      if ((qualifier_kinds(c, k) & token_kinds) == 0) continue;
      valued = true;
      for (const Bound::Copy& cp : unit.copies)
        if (cp.id == id) return true;
    }
    return !valued;
  };
  // Whether action group g's object is known to have value `id` of those kinds.
  auto has = [&](size_t g, int id, unsigned token_kinds) {
    for (size_t k = 0; k < G; ++k) {
      const Bound::Group& unit = c.groups[k];
      if (unit.parent != static_cast<int>(g) || unit.kind != 2) continue;
      if ((qualifier_kinds(c, k) & token_kinds) == 0) continue;
      for (const Bound::Copy& cp : unit.copies)
        if (cp.id == id) return true;
    }
    return false;
  };
  // Whether value token i's noun phrase is headed by "one"/"ones" ("the red
  // one", "the big red one"): only other values may stand between them.
  auto names_a_one = [&](size_t i) {
    for (size_t j = i + 1; j < n && j <= i + 3; ++j) {
      if (u.words[j] == "one" || u.words[j] == "ones") return true;
      const int jd = u.ids[j];
      if (jd < 0 || static_cast<size_t>(jd) >= attribute_word_.size() || !attribute_word_[static_cast<size_t>(jd)])
        return false;
    }
    return false;
  };
  if (have_heads) {
    for (size_t i = 0; i < n; ++i) {
      const int id = u.ids[i];
      if (id < 0 || static_cast<size_t>(id) >= attribute_word_.size() || !attribute_word_[static_cast<size_t>(id)])
        continue;
      const unsigned token_kinds = static_cast<unsigned char>(attribute_word_[static_cast<size_t>(id)]);
      // A negated value ("not the red one") contradicts the objects that have it.
      const bool neg = i < u.negated.size() && u.negated[i] != 0;
      auto fits = [&](size_t g) { return neg ? !has(g, id, token_kinds) : may_be(g, id, token_kinds); };
      for (int t = 0; t < 2; ++t) {
        bool typed = false, contradicted = true;
        for (int j : u.noun_heads[i]) {
          if (j < 0) continue;
          const int hid = u.ids[static_cast<size_t>(j)];
          const std::string& hw = u.words[static_cast<size_t>(j)];
          const double best = best_noun_mass(hid, hw);
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
            consistent = consistent || fits(g);
          }
          if (!named || consistent) {
            contradicted = false;
            break;
          }
        }
        if (!typed && contradicted && (names_a_one(i) || neg)) {
          // "the red one": no noun, but it is one of the clause's role's
          // objects (a request's "it" reads the listener's), so it
          // contradicts a command none of whose such objects can be red.
          const bool statement = t == 1 && !(i < u.asked_for.size() && u.asked_for[i]) &&
                                 !(i < u.about_request.size() && u.about_request[i]);
          bool any = false, consistent = false;
          for (size_t g = 0; g < G && !consistent; ++g) {
            const Bound::Group& grp = c.groups[g];
            if (grp.kind != 0 || !in_role(grp, statement)) continue;
            any = true;
            consistent = fits(g);
          }
          typed = any;
          contradicted = any && !consistent;
        }
        if (typed && contradicted) contra[2 * i + static_cast<size_t>(t)] = kContradictedColour;
      }
    }
  }
  return contra;
}

  // Per-token source probabilities; p_group[g * n + i] is unit g's own emission
  // (its fields' weights sum to 1 for an action group; for an optional unit
  // such as a recipient it is that unit's table alone).
  // Inside a modifier span an action group's noun and number fields give way to M.
AlignmentModel::TokenSources AlignmentModel::token_sources(const Bound& c, const EncodedUtterance& u) const {
  const size_t n = u.ids.size();
  const size_t G = c.groups.size();
  const Table& a_you = *tables_[static_cast<size_t>(table_ids_.at("A:you"))];
  const Table& a_me = *tables_[static_cast<size_t>(table_ids_.at("A:me"))];
  const Table& gen = *tables_[static_cast<size_t>(table_ids_.at("GEN"))];
  const Table& mod = *tables_[static_cast<size_t>(table_ids_.at("M"))];
  const bool have_spans = u.in_modifier.size() == n;
  TokenSources s;
  s.p_bg.resize(n);
  s.p_you.resize(n);
  s.p_me.resize(n);
  s.p_gen.resize(n);
  s.p_mod.assign(n, 0.0);
  s.p_group.resize(n * G);
  auto& [p_bg, p_you, p_me, p_gen, p_mod, p_group] = s;
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
        v += f.weight * f.table->at(id, w) * (f.number ? colour_binding(c, g, u, i) : 1.0);
      // A negated value is no mention of it ("not the red one").
      const bool negated = i < u.negated.size() && u.negated[i] != 0;
      for (const Bound::Copy& cp : c.groups[g].copies) {
        if (!negated && (id >= 0 ? id == cp.id : w == cp.word)) v += cp.weight * colour_binding(c, g, u, i);
      }
      p_group[g * n + i] = v;
    }
  }
  return s;
}

  // A very long unknown word's background probability is below the double
  // range (one character-model factor per letter), and so would be every
  // mixture at its token. All sources of such a token are divided by a common
  // factor instead, which every forward pass below carries through as a
  // constant (each is linear in one token's sources) and which is added back
  // at the end: exact, and ordinary tokens are left untouched.
double AlignmentModel::rescale_tiny_tokens(TokenSources& s, const EncodedUtterance& u) const {
  const size_t n = u.ids.size();
  const size_t G = n == 0 ? 0 : s.p_group.size() / n;
  // Plain references, not a structured binding: lambdas below capture them
  // (clang before 16 cannot capture structured bindings).
  auto& p_bg = s.p_bg;
  auto& p_you = s.p_you;
  auto& p_me = s.p_me;
  auto& p_gen = s.p_gen;
  auto& p_mod = s.p_mod;
  auto& p_group = s.p_group;
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
  return token_log_scale;
}

double AlignmentModel::evaluate(const Bound& c, const EncodedUtterance& u, bool complete,
                                Counts* counts, double weight, DeferredAdds* deferred) const {
  const size_t n = u.ids.size();
  const size_t G = c.groups.size();
  const bool have_spans = u.in_modifier.size() == n;

  const std::vector<double> contra = colour_contradictions(c, u);
  TokenSources sources = token_sources(c, u);
  const double token_log_scale = rescale_tiny_tokens(sources, u);
  // Plain references (lambdas capture them; see rescale_tiny_tokens).
  const auto& p_bg = sources.p_bg;
  const auto& p_you = sources.p_you;
  const auto& p_me = sources.p_me;
  const auto& p_gen = sources.p_gen;
  const auto& p_mod = sources.p_mod;
  const auto& p_group = sources.p_group;

  const bool enumerate = G <= static_cast<size_t>(kMaxEnumeratedGroups);
  const uint32_t all = G >= 32 ? ~0u : (1u << G) - 1u;
  const uint32_t first_mask = enumerate ? 0u : all;
  const uint32_t end_mask = enumerate ? all + 1u : all;  // exclusive; non-enumerated: one mask
  const size_t clauses = u.clause_end.size();
  // A clause's speech-act prior: "can you ...", "you bring ..." is read as a
  // request, "I'll get ...", "let me ..." as the speaker's own part.
  auto subject = [&](size_t clause) {
    return clause < u.subject.size() ? u.subject[clause] : kSubjectUnmarked;
  };
  auto p_request = [&](size_t clause) {
    switch (subject(clause)) {
      case kSubjectListener: return kMarkedClause;
      case kSubjectSpeaker: return 1 - kMarkedClause;
      default: return kRequestClause;
    }
  };

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
  auto about_request = [&](size_t i) { return i < u.about_request.size() && u.about_request[i] != 0; };
  // log of the anchored likelihood of the tokens (see below) for the k
  // mentioned action groups K, given the per-token mixtures `mix` and each
  // group's own emission emit(j, i); for a prefix, marginalised over the
  // unseen length (divided by P(N >= n), which the caller adds back).
  auto anchored_log = [&](const size_t* K, size_t k, const std::vector<double>& mx, auto&& emit) {
    const uint32_t full = (1u << k) - 1u;
    double a[2][1u << kMaxAnchors] = {};
    double b[2][1u << kMaxAnchors];
    double e[1u << kMaxAnchors];
    double single[kMaxAnchors];
    // In a clause that announces the speaker's own step, a group of the
    // listener's anchors at kOffRoleAnchor of its weight: "I'll open the
    // shed" is not how a speaker asks the listener to open it.
    auto role_factor = [&](size_t j, size_t cl) {
      return subject(cl) == kSubjectSpeaker && !in_role(c.groups[K[j]], true) ? kOffRoleAnchor : 1.0;
    };
    a[0][0] = p_request(0);
    a[1][0] = 1 - p_request(0);
    double log_scale = 0;
    size_t clause = 0;
    for (size_t i = 0; i < n; ++i) {
      for (size_t j = 0; j < k; ++j) single[j] = emit(j, i) * role_factor(j, clause);
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
            a[0][A] = p_request(clause) * sA;
            a[1][A] = (1 - p_request(clause)) * sA;
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
      // What a later request's "it" points back to is the listener's object.
      const double content_me =
          about_request(i) ? content_you
          : n_me > 0       ? kGenericShare * p_gen[i] + (1 - kGenericShare) * s_me / n_me
                           : p_gen[i];
      mix[2 * i] = contra[2 * i] * (kPiBackground * p_bg[i] + kPiAgent * p_you[i] + kPiContent * content_you);
      mix[2 * i + 1] = contra[2 * i + 1] * (kPiBackground * p_bg[i] + kPiAgent * p_me[i] + kPiContent * content_me);
    }
    size_t start = 0;
    for (size_t k = 0; k < clauses; ++k) {
      const size_t end = static_cast<size_t>(u.clause_end[k]);
      double lr = std::log(p_request(k)), ls = std::log(1 - p_request(k));
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
  const auto add = [deferred](double& slot, double v) {
    if (deferred != nullptr) deferred->emplace_back(&slot, v);
    else slot += v;
  };
  const size_t bucket = static_cast<size_t>(actions_bucket(c.num_actions));
  if (n <= static_cast<size_t>(kMaxLen)) add(counts->length[bucket][n], weight);
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
      add(counts->mention_all[grp.kind], weight * pm);
      if (on[g]) add(counts->mention_on[grp.kind], weight * pm);
    }
    size_t start = 0;
    for (size_t k = 0; k < clauses; ++k) {
      const size_t end = static_cast<size_t>(u.clause_end[k]);
      for (int t = 0; t < 2; ++t) {
        const bool speaker = t == 1;
        const double pt = std::exp(clause_log[(static_cast<size_t>(mask - first_mask) * clauses + k) * 2 + t]);
        const double wt = weight * pm * pt;
        if (wt < 1e-12) continue;
        for (size_t i = start; i < end; ++i) {
          const int id = u.ids[i];
          if (id < 0) continue;  // training tokens are always in the vocabulary
          const double p_agent = speaker ? p_me[i] : p_you[i];
          const bool own = speaker && !about_request(i);  // whose groups the content comes from
          const int active = own ? n_me : n_you;
          const double gen_share = active > 0 ? kGenericShare : 1.0;
          const double content =
              gen_share * p_gen[i] + (active > 0 ? (1 - kGenericShare) * content_sum(i, own) / active : 0.0);
          const double m = kPiBackground * p_bg[i] + kPiAgent * p_agent + kPiContent * content;
          if (m <= 0) continue;
          const double r = wt / m;
          const size_t uid = static_cast<size_t>(id);
          add(counts->bg[uid], r * kPiBackground * p_bg[i]);
          add(counts->table[static_cast<size_t>(speaker ? id_me : id_you)][uid], r * kPiAgent * p_agent);
          add(counts->table[static_cast<size_t>(id_gen)][uid], r * kPiContent * gen_share * p_gen[i]);
          if (active == 0) continue;
          const double share = r * kPiContent * (1 - kGenericShare) / active;
          for (size_t g = 0; g < G; ++g) {
            const Bound::Group& grp = c.groups[g];
            if (!on[g]) continue;
            const size_t owner = grp.parent >= 0 ? static_cast<size_t>(grp.parent) : g;
            if (!in_role(c.groups[owner], own)) continue;
            const double unit = share * (grp.parent >= 0 ? grp.unit_weight : 1.0) / den[owner];
            const bool in_mod = have_spans && u.in_modifier[i] != 0 && grp.kind == 0;
            if (in_mod) add(counts->table[static_cast<size_t>(id_mod)][uid], unit * grp.nonverb_weight * p_mod[i]);
            for (const Bound::Field& f : grp.fields) {
              if (in_mod && !f.verb) continue;
              const double e = unit * f.weight * f.table->at(id, u.words[i]);
              if (f.table_index >= 0) add(counts->table[static_cast<size_t>(f.table_index)][uid], e);
              if (f.residual) add(counts->non_copy, e);
            }
            for (const Bound::Copy& cp : grp.copies) {
              if (id == cp.id) add(counts->copy, unit * cp.weight * colour_binding(c, g, u, i));
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
                    " rho_attribute=" + std::to_string(mention_[2]) + " rho_number=" + std::to_string(mention_[3]) +
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

}  // namespace clips::lm
