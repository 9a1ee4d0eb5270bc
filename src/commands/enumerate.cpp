#include "commands/enumerate.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace clips::commands {

namespace {

using Subset = std::vector<std::size_t>;

// Calls visit(indices) for every n-subset of {0..m-1} in lexicographic order.
template <class Visit>
void for_each_combination(std::size_t m, std::size_t n, Visit visit) {
  if (n == 0 || n > m) return;
  Subset idx(n);
  for (std::size_t i = 0; i < n; ++i) idx[i] = i;
  while (true) {
    visit(idx);
    // Advance the rightmost index that can still move.
    std::size_t i = n;
    while (i > 0 && idx[i - 1] == m - n + (i - 1)) --i;
    if (i == 0) return;
    ++idx[i - 1];
    for (std::size_t j = i; j < n; ++j) idx[j] = idx[j - 1] + 1;
  }
}

bool is_agent_or_pronoun(const std::string& arg, const LanguageConfig& config) {
  return arg == config.speaker || arg == config.listener || config.is_pronoun(arg);
}

// The qualifier without its object, so (iscolor key1 red) and (iscolor key2 red) agree.
Term masked(const Term& predicate, const LanguageConfig& config) {
  Term out = predicate;
  const auto index = static_cast<std::size_t>(config.qualifier_object_arg - 1);
  if (index < out.args.size()) out.args.erase(out.args.begin() + static_cast<std::ptrdiff_t>(index));
  return out;
}

// Strings as small integers, for the per-subset tests below.
class Interner {
 public:
  int id(const std::string& s) {
    auto [it, fresh] = ids_.try_emplace(s, static_cast<int>(ids_.size()));
    return it->second;
  }

 private:
  std::unordered_map<std::string, int> ids_;
};

std::string term_key(const Term& t) {
  std::string k = t.name;
  for (const auto& a : t.args) {
    k += '\0';
    k += a;
  }
  return k;
}

// What the exclusion rules read of one salient action, as integers.
struct RuleView {
  bool speaker = false;              // its agent is the speaker
  int type = 0;                      // (agent, action name)
  std::vector<int> chain_args;       // arguments other than agents and pronouns
  std::vector<int> masked;           // its qualifiers without their object
};

std::vector<RuleView> rule_views(const std::vector<SalientAction>& salient, const LanguageConfig& config) {
  Interner ids;
  std::vector<RuleView> out(salient.size());
  for (std::size_t i = 0; i < salient.size(); ++i) {
    const SalientAction& s = salient[i];
    RuleView& v = out[i];
    v.speaker = s.agent == config.speaker;
    v.type = ids.id(s.agent + '\0' + s.action.name);
    for (const auto& arg : s.action.args)
      if (!is_agent_or_pronoun(arg, config)) v.chain_args.push_back(ids.id(arg));
    for (const auto& p : s.predicates) v.masked.push_back(ids.id(term_key(masked(p, config))));
  }
  return out;
}

// Paper rule: an object that occurs in two actions (or twice in one) makes a chain.
bool has_chain(const std::vector<const RuleView*>& subset) {
  for (std::size_t a = 0; a < subset.size(); ++a)
    for (std::size_t i = 0; i < subset[a]->chain_args.size(); ++i) {
      const int x = subset[a]->chain_args[i];
      for (std::size_t b = 0; b <= a; ++b) {
        const std::size_t end = b == a ? i : subset[b]->chain_args.size();
        for (std::size_t j = 0; j < end; ++j)
          if (subset[b]->chain_args[j] == x) return true;
      }
    }
  return false;
}

// Within each (agent, action) group, the members may use at most
// max_qualifier_values_per_action_type distinct qualifiers, counted from the
// first member's (mDKG: one colour; VH: two item types).
bool qualifiers_consistent(const std::vector<const RuleView*>& subset, const LanguageConfig& config) {
  const auto limit = static_cast<std::size_t>(config.max_qualifier_values_per_action_type);
  if (limit == 0) return true;
  std::vector<int> types;
  for (const auto* s : subset)
    if (std::find(types.begin(), types.end(), s->type) == types.end()) types.push_back(s->type);
  std::vector<int> seen;
  for (int type : types) {
    const RuleView* first = nullptr;
    std::size_t members = 0;
    for (const auto* s : subset)
      if (s->type == type) {
        if (!first) first = s;
        ++members;
      }
    if (members < 2) continue;
    seen = first->masked;
    bool past_first = false;
    for (const auto* s : subset) {
      if (s->type != type) continue;
      if (!past_first) {
        past_first = true;
        continue;
      }
      for (int m : s->masked) {
        if (std::find(seen.begin(), seen.end(), m) != seen.end()) continue;
        if (seen.size() >= limit) return false;
        seen.push_back(m);
      }
    }
  }
  return true;
}

// Calls visit(indices) for every subset that passes the speaker, action-type,
// chain and qualifier rules, in enumeration order.
template <class Visit>
void for_each_selected_subset(const std::vector<SalientAction>& salient, const LanguageConfig& config, Visit visit) {
  const std::vector<RuleView> views = rule_views(salient, config);
  Subset usable;
  for (std::size_t i = 0; i < salient.size(); ++i)
    if (config.speaker_actions != SpeakerActionRule::ExcludeAll || salient[i].agent != config.speaker)
      usable.push_back(i);

  const std::size_t max_size = std::min<std::size_t>(static_cast<std::size_t>(config.max_command_actions),
                                                     usable.size());
  const auto max_types = static_cast<std::size_t>(config.max_action_types);
  std::vector<const RuleView*> subset;
  Subset indices;
  std::vector<int> types;
  for (std::size_t n = 1; n <= max_size; ++n) {
    for_each_combination(usable.size(), n, [&](const Subset& combo) {
      subset.clear();
      indices.clear();
      for (std::size_t c : combo) {
        indices.push_back(usable[c]);
        subset.push_back(&views[usable[c]]);
      }
      if (config.speaker_actions == SpeakerActionRule::ExcludeSpeakerOnlyCommands &&
          std::all_of(subset.begin(), subset.end(), [](const RuleView* s) { return s->speaker; }))
        return;
      // The reference applies these two rules only above the type limit
      // (n >= 3 with the defaults), where they can first fail.
      if (n > max_types) {
        types.clear();
        for (const auto* s : subset)
          if (std::find(types.begin(), types.end(), s->type) == types.end()) types.push_back(s->type);
        if (types.size() > max_types) return;
      }
      if (config.exclude_chains && has_chain(subset)) return;
      if (n > max_types && !qualifiers_consistent(subset, config)) return;
      visit(indices);
    });
  }
}

// What lift_command reads of one salient action, as integers, and a key of
// a subset that fixes its lifted command: the actions' names and pronouns,
// each object as (name stem, its number among the stem's variables) with its
// type where it first appears, the predicates with the same objects and the
// other arguments as strings. Equal keys give equal lifted commands (the key
// holds everything lift_command reads), so a repeated key needs no lifting.
class LiftKeys {
 public:
  LiftKeys(const std::vector<SalientAction>& salient, const LanguageConfig& config, const TypeLookup& type_of)
      : config_(config), views_(salient.size()) {
    const auto object_index = static_cast<std::size_t>(config.qualifier_object_arg - 1);
    for (std::size_t i = 0; i < salient.size(); ++i) {
      const SalientAction& s = salient[i];
      View& v = views_[i];
      v.name = ids_.id(s.action.name);
      for (const auto& arg : s.action.args) {
        const std::string pronoun = config.to_pronoun(arg);
        const bool is_agent = pronoun != arg || config.is_pronoun(arg);
        if (is_agent || is_variable(arg)) {
          v.args.push_back({false, ids_.id(pronoun)});
        } else {
          const int o = ids_.id(arg);
          v.args.push_back({true, o});
          if (!type_of_.count(o)) type_of_[o] = ids_.id(type_of(arg));
        }
      }
      for (const auto& p : s.predicates) {
        std::vector<int> args;
        for (const auto& a : p.args) args.push_back(ids_.id(a));
        v.predicates.push_back({ids_.id(p.name), std::move(args)});
        // lift_command's qualifier_value: the first qualifier predicate naming
        // the object that has another argument.
        if (p.name != config.qualifier || object_index >= p.args.size()) continue;
        for (std::size_t k = 0; k < p.args.size(); ++k)
          if (k != object_index) {
            v.values.push_back({ids_.id(p.args[object_index]), ids_.id(p.args[k])});
            break;
          }
      }
    }
  }

  // The key of the subset `indices` (written to `key`).
  void key(const Subset& indices, std::string& key) {
    key.clear();
    objects_.clear();
    stems_.clear();
    auto put = [&key](int x) { key.append(reinterpret_cast<const char*>(&x), sizeof x); };
    auto stem_of = [&](int o) {
      if (config_.variable_naming == VariableNaming::QualifierValue)
        for (std::size_t i : indices)
          for (const auto& [obj, value] : views_[i].values)
            if (obj == o) return value;
      return type_of_.at(o);
    };
    auto variable = [&](int o) -> std::pair<int, int> {
      for (const auto& [obj, sv] : objects_)
        if (obj == o) return sv;
      return {-1, -1};
    };
    put(static_cast<int>(indices.size()));
    for (std::size_t i : indices) {
      const View& v = views_[i];
      put(v.name);
      put(static_cast<int>(v.args.size()));
      for (const auto& [object, id] : v.args) {
        if (!object) {
          put(-1);
          put(id);
          continue;
        }
        auto sv = variable(id);
        if (sv.first < 0) {
          const int stem = stem_of(id);
          int k = 1;
          for (auto& [st, count] : stems_)
            if (st == stem) k = ++count;
          if (k == 1) stems_.push_back({stem, 1});
          sv = {stem, k};
          objects_.push_back({id, sv});
          put(-2);
          put(type_of_.at(id));
        }
        put(sv.first);
        put(sv.second);
      }
    }
    int predicates = 0;
    for (std::size_t i : indices) predicates += static_cast<int>(views_[i].predicates.size());
    put(predicates);
    for (std::size_t i : indices)
      for (const auto& [name, args] : views_[i].predicates) {
        put(name);
        put(static_cast<int>(args.size()));
        for (int a : args) {
          const auto sv = variable(a);
          if (sv.first < 0) {
            put(-1);
            put(a);
          } else {
            put(sv.first);
            put(sv.second);
          }
        }
      }
  }

 private:
  struct View {
    int name = 0;
    std::vector<std::pair<bool, int>> args;  // (is an object, string id)
    std::vector<std::pair<int, std::vector<int>>> predicates;
    std::vector<std::pair<int, int>> values;  // (object, qualifier value)
  };
  const LanguageConfig& config_;
  Interner ids_;
  std::vector<View> views_;
  std::unordered_map<int, int> type_of_;
  std::vector<std::pair<int, std::pair<int, int>>> objects_;  // object -> (stem, number)
  std::vector<std::pair<int, int>> stems_;                    // stem -> variables so far
};

// A string equal for two commands exactly when Command::operator== holds
// (actions, predicates, variables in order; every field length-prefixed).
std::string dedup_key(const Command& c) {
  std::string k;
  auto put = [&k](const std::string& s) {
    k += std::to_string(s.size());
    k += ':';
    k += s;
  };
  auto terms = [&](const std::vector<Term>& ts) {
    k += std::to_string(ts.size());
    k += '|';
    for (const Term& t : ts) {
      put(t.name);
      k += std::to_string(t.args.size());
      k += '|';
      for (const auto& a : t.args) put(a);
    }
  };
  terms(c.actions);
  terms(c.predicates);
  k += std::to_string(c.variables.size());
  k += '|';
  for (const Variable& v : c.variables) {
    put(v.name);
    put(v.type);
  }
  return k;
}

}  // namespace

std::vector<std::vector<std::size_t>> select_command_subsets(const std::vector<SalientAction>& salient,
                                                             const LanguageConfig& config) {
  std::vector<Subset> selected;
  for_each_selected_subset(salient, config, [&](const Subset& indices) { selected.push_back(indices); });
  return selected;
}

std::vector<Command> enumerate_commands(const std::vector<SalientAction>& salient, const LanguageConfig& config,
                                        const TypeLookup& type_of) {
  // Commands in order of first appearance. The subsets are streamed, not
  // stored; a subset whose key was seen lifts to a command already met, so
  // only new keys are lifted, and a hash set of the commands' own keys finds
  // the remaining repeats (a linear search made this quadratic).
  std::vector<Command> commands;
  if (!type_of) throw std::invalid_argument("lift_command needs an object-type lookup");
  LiftKeys keys(salient, config, type_of);
  std::unordered_set<std::string> seen_keys, seen_commands;
  std::vector<SalientAction> subset;
  std::string key;
  for_each_selected_subset(salient, config, [&](const Subset& indices) {
    keys.key(indices, key);
    if (!seen_keys.insert(key).second) return;
    subset.clear();
    for (std::size_t i : indices) subset.push_back(salient[i]);
    Command cmd = lift_command(subset, config, type_of);
    if (seen_commands.insert(dedup_key(cmd)).second) commands.push_back(std::move(cmd));
  });
  return commands;
}

std::vector<Command> enumerate_literal_candidates(const std::vector<Term>& candidate_actions,
                                                  const LanguageConfig& config,
                                                  const QualifierLookup& qualifier_of,
                                                  const TypeLookup& type_of) {
  return enumerate_commands(extract_salient(candidate_actions, config, qualifier_of), config, type_of);
}

std::vector<double> uniform_command_weights(std::size_t command_count) {
  if (command_count == 0) return {};
  return std::vector<double>(command_count, 1.0 / static_cast<double>(command_count));
}

}  // namespace clips::commands
