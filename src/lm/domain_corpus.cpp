#include "lm/domain_corpus.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <random>
#include <set>
#include <string_view>
#include <utility>

#include "lm/alignment_model.hpp"
#include "lm/language_model.hpp"
#include "lm/wordnet_lexicon.hpp"
#include "util/numbered_names.hpp"

namespace clips::lm {
namespace {

// The share of noun phrases that name an object by a declared supertype
// (fitted on the dev halves: 0.15, 0.3 and 0.45 tried; docs/decisions.md).
constexpr double kSupertypeShare = 0.3;

// A fixed-seed generator with its own reductions: std:: distributions differ
// between standard libraries, and the corpus must not.
class Dice {
 public:
  explicit Dice(uint64_t seed) : engine_(seed) {}
  size_t below(size_t n) { return n == 0 ? 0 : static_cast<size_t>(engine_() % n); }
  bool chance(double p) { return static_cast<double>(engine_() >> 11) * 0x1.0p-53 < p; }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[below(v.size())];
  }

 private:
  std::mt19937_64 engine_;
};

// A PDDL name as words: split on '-', '_' and camelCase, digits dropped ("big-ish" -> "big ish").
std::string name_as_words(std::string_view name) {
  std::string out;
  char prev = 0;
  for (char c : name) {
    const bool upper = std::isupper(static_cast<unsigned char>(c)) != 0;
    if (c == '-' || c == '_' || c == ' ' || (upper && std::islower(static_cast<unsigned char>(prev)))) {
      if (!out.empty() && out.back() != ' ') out.push_back(' ');
    }
    if (std::isalpha(static_cast<unsigned char>(c))) out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    prev = c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// A number in words: "three" (cardinal) or "third" (ordinal); digits beyond twelve.
std::string number_in_words(const std::string& digits, bool ordinal) {
  static const std::vector<std::string> cardinal = {"zero", "one", "two", "three", "four", "five", "six",
                                                    "seven", "eight", "nine", "ten", "eleven", "twelve"};
  static const std::vector<std::string> ordinals = {"zeroth", "first", "second", "third", "fourth", "fifth", "sixth",
                                                    "seventh", "eighth", "ninth", "tenth", "eleventh", "twelfth"};
  const int n = digits.size() <= 3 ? std::stoi(digits) : -1;
  if (n < 0 || n > 12) return ordinal ? digits + "th" : digits;
  return ordinal ? ordinals[static_cast<size_t>(n)] : cardinal[static_cast<size_t>(n)];
}

// Words of an action or type: the pack's own words, then WordNet's.
std::vector<std::string> phrases_for(const std::string& name, const std::map<std::string, std::vector<std::string>>& extra,
                                     bool verb, const NounSenses& senses = {}) {
  std::vector<std::string> out;
  if (auto it = extra.find(name); it != extra.end())
    for (const std::string& w : it->second) out.push_back(w);
  WordNetLexicon& wn = WordNetLexicon::instance();
  const std::string words = name_as_words(name);
  const auto sense = senses.find(name);
  for (const std::string& w : verb ? wn.verb_phrases(words) : wn.noun_phrases(words, sense == senses.end() ? 0 : sense->second))
    if (std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
  if (out.empty()) out.push_back(words);
  return out;
}

// One action of a command: who does it, to what, and whether it hands to the speaker.
struct PlannedAction {
  const CommandActionRule* rule = nullptr;
  const DomainActionSchema* schema = nullptr;
  bool speaker_acts = false;
  const DomainObject* focal = nullptr;
  std::vector<const QualifierFact*> facts;  // the focal object's qualifiers the command states
  const QualifierFact* location = nullptr;  // where it is, when the command states it
  const DomainObject* destination = nullptr;  // where it goes, when the command states it
};

class Generator {
 public:
  Generator(const DomainDescription& d, const DomainCorpusOptions& o)
      : d_(d), o_(o), dice_(o.seed), senses_(domain_noun_senses(d)) {
    for (const DomainObject& obj : d_.objects) type_of_[obj.name] = obj.type;
    for (const CommandActionRule& r : d_.command_actions) {
      auto s = std::find_if(d_.actions.begin(), d_.actions.end(),
                            [&](const DomainActionSchema& a) { return a.name == r.action; });
      if (s == d_.actions.end()) throw LmError("domain corpus: the command grammar names an unknown action '" + r.action + "'");
      const int n = static_cast<int>(s->parameter_types.size());
      if (r.agent_arg < 1 || r.agent_arg > n || r.focal_arg < 1 || r.focal_arg > n || r.agent_arg == r.focal_arg)
        throw LmError("domain corpus: bad agent/focal position for action '" + r.action + "'");
      rules_.emplace_back(&r, &*s);
    }
  }

  std::vector<TrainingPair> run() {
    // One-action commands: every action, object and choice of stated qualifiers.
    for (const auto& [rule, schema] : rules_) {
      for (const DomainObject* obj : focal_objects(*rule, *schema)) {
        const std::vector<const QualifierFact*> facts = facts_of(obj->name);
        std::vector<std::vector<const QualifierFact*>> variants = {facts};
        if (facts.size() > 1)
          for (const QualifierFact* f : facts) variants.push_back({f});
        if (!facts.empty()) variants.emplace_back();
        for (const auto& stated : variants) {
          PlannedAction a{rule, schema, false, obj, stated};
          for (int k = 0; k < o_.utterances_per_command; ++k) emit({a}, one_action_utterance(a));
          // The same with where the object is, said as a place ("from the rack").
          if (const QualifierFact* at = location_of(obj->name)) {
            a.location = at;
            for (int k = 0; k < o_.utterances_per_command; ++k) emit({a}, one_action_utterance(a));
            a.location = nullptr;
          }
          // And with where it goes ("to the border"), for a few of the places.
          const std::vector<const DomainObject*> places = destinations(*rule, *schema);
          for (int k = 0; k < std::min<int>(2, static_cast<int>(places.size())); ++k) {
            a.destination = dice_.pick(places);
            for (int u = 0; u < o_.utterances_per_command; ++u) emit({a}, one_action_utterance(a));
          }
        }
      }
    }
    // Two listener actions, and joint commands (the speaker's part first).
    for (int k = 0; k < o_.two_action_commands; ++k) {
      auto a = random_action(false), b = random_action(false);
      if (!a || !b || a->focal == b->focal) continue;
      emit({*a, *b}, two_action_utterance(*a, *b));
    }
    for (int k = 0; k < o_.joint_commands; ++k) {
      auto mine = random_action(true), yours = random_action(false);
      if (!mine || !yours || mine->focal == yours->focal) continue;
      emit({*mine, *yours}, joint_utterance(*mine, *yours));
    }
    goal_statements();
    return std::move(pairs_);
  }

 private:
  bool is_a(std::string type, const std::string& ancestor) const {
    for (int guard = 0; guard < 64; ++guard) {
      if (type == ancestor) return true;
      auto it = d_.parent_type.find(type);
      if (it == d_.parent_type.end()) return ancestor == "object";
      type = it->second;
    }
    return false;
  }
  std::string type_of(const std::string& object) const {
    auto it = type_of_.find(object);
    return it == type_of_.end() ? "" : it->second;
  }
  bool agent_type(const std::string& param_type) const {
    return is_a(type_of(d_.speaker), param_type) || is_a(type_of(d_.listener), param_type);
  }
  // The speaker is the recipient of an action with a second agent parameter.
  bool hands_over(const CommandActionRule& r, const DomainActionSchema& s) const {
    for (size_t j = 0; j < s.parameter_types.size(); ++j)
      if (static_cast<int>(j) + 1 != r.agent_arg && static_cast<int>(j) + 1 != r.focal_arg && agent_type(s.parameter_types[j]))
        return true;
    return false;
  }
  std::vector<const DomainObject*> focal_objects(const CommandActionRule& r, const DomainActionSchema& s) const {
    std::vector<const DomainObject*> out;
    const std::string& want = s.parameter_types[static_cast<size_t>(r.focal_arg - 1)];
    for (const DomainObject& obj : d_.objects)
      if (obj.name != d_.speaker && obj.name != d_.listener && is_a(obj.type, want)) out.push_back(&obj);
    return out;
  }
  // The places an action may leave its focal object at (its destination
  // parameter's objects), none for an action without one.
  std::vector<const DomainObject*> destinations(const CommandActionRule& r, const DomainActionSchema& s) const {
    std::vector<const DomainObject*> out;
    if (r.destination_arg < 1 || r.destination_arg > static_cast<int>(s.parameter_types.size())) return out;
    const std::string& want = s.parameter_types[static_cast<size_t>(r.destination_arg - 1)];
    for (const DomainObject& obj : d_.objects)
      if (obj.name != d_.speaker && obj.name != d_.listener && is_a(obj.type, want) &&
          WordNetLexicon::instance().sayable_name(obj.name))
        out.push_back(&obj);
    return out;
  }
  bool numbered(const std::string& name) const {
    return std::find(d_.numbered.begin(), d_.numbered.end(), name) != d_.numbered.end();
  }
  // A place as commands print it: marked with its number when people say it.
  std::string printed_place(const std::string& name) const {
    return numbered(name) ? util::number_marked(name) : name;
  }
  // A numbered place as people say it: "shelf 3", "shelf three", "shelf
  // number 3", "the third shelf" (no article but for the ordinal form).
  std::string said_number(const std::string& name) {
    const std::string marked = util::number_marked(name);
    const std::string stem = name_as_words(marked.substr(0, marked.find('#')));
    const std::string digits = marked.substr(marked.find('#') + 1);
    switch (dice_.below(4)) {
      case 0: return stem + " " + digits;
      case 1: return stem + " " + number_in_words(digits, false);
      case 2: return stem + " number " + digits;
      default: return "the " + number_in_words(digits, true) + " " + stem;
    }
  }
  // "<preposition> the <place>", or for a numbered place "<preposition> <its number phrase>".
  std::string place_after(const std::string& prep_the, const std::string& name) {
    if (!numbered(name)) return prep_the + " " + name_as_words(name);
    std::string prep = prep_the;
    if (prep.size() >= 4 && prep.compare(prep.size() - 4, 4, " the") == 0) prep.resize(prep.size() - 4);
    return prep + " " + said_number(name);
  }
  const QualifierFact* location_of(const std::string& object) const {
    for (const QualifierFact& f : d_.locations)
      if (f.object == object) return &f;
    return nullptr;
  }
  std::vector<const QualifierFact*> facts_of(const std::string& object) const {
    std::vector<const QualifierFact*> out;
    for (const QualifierFact& f : d_.qualifiers)
      if (f.object == object) out.push_back(&f);
    return out;
  }

  std::optional<PlannedAction> random_action(bool speaker_acts) {
    std::vector<std::pair<const CommandActionRule*, const DomainActionSchema*>> usable;
    for (const auto& rs : rules_)
      if (!speaker_acts || !hands_over(*rs.first, *rs.second)) usable.push_back(rs);  // the speaker hands nothing to itself
    if (usable.empty()) return std::nullopt;
    const auto [rule, schema] = dice_.pick(usable);
    const std::vector<const DomainObject*> objects = focal_objects(*rule, *schema);
    if (objects.empty()) return std::nullopt;
    PlannedAction a{rule, schema, speaker_acts, dice_.pick(objects), {}};
    std::vector<const QualifierFact*> facts = facts_of(a.focal->name);
    if (facts.size() > 1 && dice_.chance(0.5)) facts = {dice_.pick(facts)};
    a.facts = facts;
    if (dice_.chance(0.3)) a.location = location_of(a.focal->name);
    if (const auto places = destinations(*rule, *schema); !places.empty() && dice_.chance(0.4))
      a.destination = dice_.pick(places);
    return a;
  }

  // ---- commands --------------------------------------------------------------

  // Printed like the few-shot examples: variables named by type and a per-type
  // counter in order of appearance, then `where` and the stated qualifiers.
  std::string command_text(const std::vector<PlannedAction>& actions) const {
    std::map<std::string, std::string> variable;  // object -> variable
    std::map<std::string, int> counter;
    std::string out, where;
    for (const PlannedAction& a : actions) {
      auto [it, fresh] = variable.emplace(a.focal->name, "");
      if (fresh)
        it->second = a.rule->focal_is_place ? printed_place(a.focal->name)
                                            : a.focal->type + std::to_string(++counter[a.focal->type]);
      out += (out.empty() ? "(" : " (") + a.schema->name;
      for (size_t j = 0; j < a.schema->parameter_types.size(); ++j) {
        const int pos = static_cast<int>(j) + 1;
        if (pos == a.rule->agent_arg) {
          out += " " + (a.speaker_acts ? d_.speaker_pronoun : d_.listener_pronoun);
        } else if (pos == a.rule->focal_arg) {
          out += " " + it->second;
        } else if (agent_type(a.schema->parameter_types[j])) {
          out += " " + (a.speaker_acts ? d_.listener_pronoun : d_.speaker_pronoun);
        }
      }
      out += ")";
      for (const QualifierFact* f : a.facts) where += " (" + f->predicate + " " + it->second + " " + f->value + ")";
      if (a.location)
        where += " (" + a.location->predicate + " " + it->second + " " + printed_place(a.location->value) + ")";
      if (a.destination)
        where += " (" + d_.destination_predicate + " " + it->second + " " + printed_place(a.destination->name) + ")";
    }
    return where.empty() ? out : out + " where" + where;
  }

  void emit(const std::vector<PlannedAction>& actions, std::string utterance) {
    if (!utterance.empty()) utterance[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(utterance[0])));
    const std::string command = command_text(actions);
    // The same pair twice would only weigh it double.
    if (!seen_.insert(command + "\t" + utterance).second) return;
    pairs_.push_back(TrainingPair{command, utterance, 1.0, "generated pair " + std::to_string(pairs_.size() + 1)});
  }

  // ---- utterances ----------------------------------------------------------------

  // Phrases come most typical first: the name's own phrase a third of the
  // time, else the others with weights falling as 1 / rank.
  std::string ranked_pick(const std::vector<std::string>& phrases, double first) {
    if (phrases.size() == 1 || dice_.chance(first)) return phrases.front();
    double total = 0;
    for (size_t i = 1; i < phrases.size(); ++i) total += 1.0 / static_cast<double>(i);
    double x = static_cast<double>(dice_.below(1u << 20)) / static_cast<double>(1u << 20) * total;
    for (size_t i = 1; i < phrases.size(); ++i) {
      x -= 1.0 / static_cast<double>(i);
      if (x < 0) return phrases[i];
    }
    return phrases.back();
  }
  std::string verb(const PlannedAction& a) { return ranked_pick(phrases_for(a.schema->name, d_.extra_verbs, true), 0.3); }
  std::string noun(const std::string& type, bool plural) {
    // Now and then by a supertype the domain declares ("the sample" for a
    // culture, "a tool" for a trowel): the domain's own hypernyms, which
    // WordNet may not know as such.
    std::string named = type;
    if (const std::vector<std::string> up = supertypes(type); !up.empty() && dice_.chance(kSupertypeShare))
      named = dice_.pick(up);
    const std::string n = named == type ? ranked_pick(phrases_for(type, d_.extra_nouns, false, senses_), 0.7)
                                        : phrases_for(named, d_.extra_nouns, false, senses_).front();
    return plural ? WordNetLexicon::instance().plural(n) : n;
  }
  // The declared ancestors of a type, nearest first, without `object` (every
  // type's). Only focal objects of commands are named, so these are kinds of
  // things people fetch, not of agents or places.
  std::vector<std::string> supertypes(const std::string& type) const {
    std::vector<std::string> out;
    std::string t = type;
    for (int guard = 0; guard < 64; ++guard) {
      auto it = d_.parent_type.find(t);
      if (it == d_.parent_type.end() || it->second == "object") break;
      t = it->second;
      out.push_back(t);
    }
    return out;
  }
  // The adjectives of an object: some, all or none of its stated qualifiers.
  std::vector<std::string> adjectives(const PlannedAction& a) {
    std::vector<std::string> out;
    if (a.facts.empty() || dice_.chance(0.15)) return out;
    if (a.facts.size() > 1 && dice_.chance(0.4)) return {name_as_words(dice_.pick(a.facts)->value)};
    for (const QualifierFact* f : a.facts) out.push_back(name_as_words(f->value));
    return out;
  }
  // "the big plank", "a metal saw", "the big one" (the pronoun "one" when a
  // qualifier alone picks the object out, as speakers do when several kinds share it).
  std::string noun_phrase(const PlannedAction& a) {
    const std::vector<std::string> adj = adjectives(a);
    std::string np = dice_.chance(0.75) ? "the" : "a";
    for (const std::string& x : adj) np += " " + x;
    std::string head = !adj.empty() && dice_.chance(0.3) ? std::string("one") : noun(a.focal->type, false);
    // A place is said by its name ("the greenhouse"), as commands print it,
    // unless the name only numbers its type (fridge1). The type's noun is
    // drawn all the same, so the rest of the corpus draws as before.
    if (a.rule->focal_is_place && head != "one" && numbered(a.focal->name)) {
      np = said_number(a.focal->name);  // "door 2", "the second door"
      head.clear();
    } else if (a.rule->focal_is_place && head != "one" && name_as_words(a.focal->name) != name_as_words(a.focal->type)) {
      head = name_as_words(a.focal->name);
    }
    if (!head.empty()) np += " " + head;
    if (a.location) {
      static const std::vector<std::string> preps = {"from the", "in the", "on the", "at the", "over at the",
                                                     "by the", "from the"};
      np += " " + place_after(dice_.pick(preps), a.location->value);
    }
    return np;
  }
  std::string verb_phrase(const PlannedAction& a, const std::string& np) {
    std::string vp = object_phrase(a, np);
    if (a.destination) {
      static const std::vector<std::string> to = {"to the", "over to the", "at the", "in the", "on the",
                                                  "by the", "to the", "down at the", "into the"};
      vp += " " + place_after(dice_.pick(to), a.destination->name);
    }
    return vp;
  }
  // The verb and its object, with the recipient of a hand-over.
  std::string object_phrase(const PlannedAction& a, const std::string& np) {
    const std::string v = verb(a);
    const bool phrasal = v.find(' ') != std::string::npos;
    if (!a.speaker_acts && hands_over(*a.rule, *a.schema)) {
      static const std::vector<std::string> to_me = {" to me", " over to me", " over here", " for me"};
      if (!phrasal && dice_.chance(0.5)) return v + " me " + np;
      return v + " " + np + dice_.pick(to_me);
    }
    if (phrasal && dice_.chance(0.3)) {  // "pick the plank up"
      const size_t space = v.rfind(' ');
      return v.substr(0, space) + " " + np + v.substr(space);
    }
    return v + " " + np;
  }

  std::string request(const std::string& vp) {
    static const std::vector<std::string> before = {"can you ", "could you ", "please ", "", "would you ",
                                                    "can you please ", "I need you to ", "will you "};
    static const std::vector<std::string> after = {"?", "?", ".", "!", "?", "?", ".", "?"};
    const size_t k = dice_.below(before.size());
    return before[k] + vp + after[k];
  }
  std::string statement(const std::string& vp) {
    static const std::vector<std::string> frames = {"I'll ", "I will ", "I'm going to ", "let me ", "I'm gonna "};
    return dice_.pick(frames) + vp;
  }

  std::string one_action_utterance(const PlannedAction& a) {
    const std::string np = noun_phrase(a);
    if (hands_over(*a.rule, *a.schema) && dice_.chance(0.15)) {
      static const std::vector<std::string> need = {"I need ", "I want ", "can I have ", "I could use "};
      static const std::vector<std::string> end = {".", ".", "?", "."};
      const size_t k = dice_.below(need.size());
      return need[k] + np + end[k];
    }
    return request(verb_phrase(a, np));
  }
  std::string two_action_utterance(const PlannedAction& a, const PlannedAction& b) {
    const std::vector<std::string> adj_a = adjectives(a);
    // Same action on two objects of one type: "bring me both planks".
    if (a.schema == b.schema && a.focal->type == b.focal->type && !a.rule->focal_is_place && dice_.chance(0.5)) {
      static const std::vector<std::string> both = {"both", "the two", "two", "both of the"};
      std::string np = dice_.pick(both);
      if (a.facts.size() == 1 && b.facts.size() == 1 && a.facts[0]->value == b.facts[0]->value)
        np += " " + name_as_words(a.facts[0]->value);
      np += " " + noun(a.focal->type, true);
      return request(verb_phrase(a, np));
    }
    const std::string joiner = dice_.chance(0.7) ? " and " : ", then ";
    return request(verb_phrase(a, noun_phrase(a)) + joiner + verb_phrase(b, noun_phrase(b)));
  }
  std::string joint_utterance(const PlannedAction& mine, const PlannedAction& yours) {
    const std::string own = statement(verb_phrase(mine, noun_phrase(mine)));
    const std::string ask = request(verb_phrase(yours, noun_phrase(yours)));
    if (dice_.chance(0.25)) return "you " + verb_phrase(yours, noun_phrase(yours)) + " and " + own + ".";
    return own + ", " + ask;
  }

  // "(make me ?goal1) where (named ?goal1 pot) (named ?goal1 roses)" <->
  // "I'd like to pot the roses", "we're making the frame", ...
  void goal_statements() {
    // Type nouns stay nouns: a goal word that is also a type ("the rose" in
    // "pot-rose") is not made a name, or the noun would lose the mass that
    // binds qualifiers to it (UtteranceModel::goal_statement skips them too).
    std::set<std::string> type_words;
    for (const auto& [child, parent] : d_.parent_type) type_words.insert({child, parent});
    for (const DomainObject& o : d_.objects) type_words.insert(o.type);
    const std::vector<std::string>& names = d_.goal_names;
    if (names.empty()) return;
    static const std::vector<std::string> frames = {
        "we're making the {}.", "I want to make the {}.", "I'd like to do the {}.", "today I'm doing the {}.",
        "I'm going for the {}.", "I want the {}.", "let's make the {}.", "I'm working on the {}.",
        "the {}, please.", "we need to get the {} done.", "I'm trying to make a {}.", "I want to {}."};
    for (int k = 0; k < o_.goal_statements; ++k) {
      const std::string& name = dice_.pick(names);
      std::string words = name_as_words(name);
      std::string where;
      size_t start = 0;
      while (start < words.size()) {
        size_t end = words.find(' ', start);
        if (end == std::string::npos) end = words.size();
        const std::string w = words.substr(start, end - start);
        if (w.size() > 1 && !type_words.count(w)) where += " (named goal1 " + w + ")";
        start = end + 1;
      }
      // A numbered place in the goal's name is said with its number ("shelf 3").
      if (!d_.numbered.empty()) {
        std::string said, part;
        bool any = false;
        for (char ch : name + "-") {
          if (ch != '-' && ch != '_' && ch != ' ') {
            part.push_back(ch);
            continue;
          }
          if (part.empty()) continue;
          if (numbered(part)) {
            const std::string marked = util::number_marked(part);
            where += " (named goal1 " + marked.substr(marked.find('#') + 1) + ")";
            said += (said.empty() ? "" : " ") + said_number(part);
            any = true;
          } else if (const std::string w = name_as_words(part); !w.empty()) {
            said += (said.empty() ? "" : " ") + w;
          }
          part.clear();
        }
        if (any) words = said;
      }
      if (where.empty()) continue;
      std::string u = dice_.pick(frames);
      u.replace(u.find("{}"), 2, words);
      const std::string command = "(make " + d_.speaker_pronoun + " goal1) where" + where;
      if (!u.empty()) u[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(u[0])));
      if (seen_.insert(command + "\t" + u).second)
        pairs_.push_back(TrainingPair{command, u, 1.0, "generated pair " + std::to_string(pairs_.size() + 1)});
    }
  }

  const DomainDescription& d_;
  const DomainCorpusOptions& o_;
  Dice dice_;
  std::map<std::string, std::string> type_of_;
  std::vector<std::pair<const CommandActionRule*, const DomainActionSchema*>> rules_;
  NounSenses senses_;
  std::vector<TrainingPair> pairs_;
  std::set<std::string> seen_;
};

}  // namespace

std::vector<std::string> domain_noun_types(const DomainDescription& domain) {
  std::set<std::string> focal_types;
  for (const CommandActionRule& r : domain.command_actions)
    for (const DomainActionSchema& s : domain.actions)
      if (s.name == r.action && r.focal_arg >= 1 && r.focal_arg <= static_cast<int>(s.parameter_types.size()))
        focal_types.insert(s.parameter_types[static_cast<size_t>(r.focal_arg - 1)]);
  std::set<std::string> types;
  for (const DomainObject& obj : domain.objects) {
    std::vector<std::string> chain{obj.type};
    for (int guard = 0; guard < 64 && !focal_types.count(chain.back()); ++guard) {
      const auto it = domain.parent_type.find(chain.back());
      if (it == domain.parent_type.end()) break;
      chain.push_back(it->second);
    }
    if (focal_types.count(chain.back())) types.insert(chain.begin(), chain.end());
  }
  types.erase("object");
  return {types.begin(), types.end()};
}

NounSenses domain_noun_senses(const DomainDescription& domain) {
  return WordNetLexicon::instance().domain_noun_senses(domain.parent_type, domain_noun_types(domain));
}

std::vector<TrainingPair> generate_domain_corpus(const DomainDescription& domain, const DomainCorpusOptions& options) {
  return Generator(domain, options).run();
}

EmbeddedModelOptions embedded_options_for_domain(const DomainDescription& domain, const DomainCorpusOptions& options) {
  EmbeddedModelOptions o;
  o.corpus_files.clear();
  o.extra_corpus = generate_domain_corpus(domain, options);
  o.noun_senses = domain_noun_senses(domain);
  return o;
}

std::shared_ptr<AlignmentModel> train_domain_model(const DomainDescription& domain, const std::vector<TrainingPair>& fewshot,
                                                   double fewshot_weight, int em_iterations,
                                                   const DomainCorpusOptions& options) {
  std::vector<TrainingPair> pairs = generate_domain_corpus(domain, options);
  for (TrainingPair p : fewshot) {
    p.weight = fewshot_weight;
    pairs.push_back(std::move(p));
  }
  return AlignmentModel::train(pairs, em_iterations, domain_noun_senses(domain));
}

}  // namespace clips::lm
