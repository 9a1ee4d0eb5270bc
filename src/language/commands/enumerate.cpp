#include "language/commands/enumerate.hpp"

#include <algorithm>
#include <set>
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

std::pair<std::string, std::string> action_type(const SalientAction& s) { return {s.agent, s.action.name}; }

bool is_agent_or_pronoun(const std::string& arg, const LanguageConfig& config) {
  return arg == config.speaker || arg == config.listener || config.is_pronoun(arg);
}

// Paper rule: an object that occurs in two actions makes a chain.
bool has_chain(const std::vector<const SalientAction*>& subset, const LanguageConfig& config) {
  std::set<std::string> seen;
  for (const auto* s : subset)
    for (const auto& arg : s->action.args) {
      if (is_agent_or_pronoun(arg, config)) continue;
      if (!seen.insert(arg).second) return true;
    }
  return false;
}

// The qualifier without its object, so (iscolor key1 red) and (iscolor key2 red) agree.
Term masked(const Term& predicate, const LanguageConfig& config) {
  Term out = predicate;
  const auto index = static_cast<std::size_t>(config.qualifier_object_arg - 1);
  if (index < out.args.size()) out.args.erase(out.args.begin() + static_cast<std::ptrdiff_t>(index));
  return out;
}

// Within each (agent, action) group, the members may use at most
// max_qualifier_values_per_action_type distinct qualifiers, counted from the
// first member's (mDKG: one colour; VH: two item types).
bool qualifiers_consistent(const std::vector<const SalientAction*>& subset, const LanguageConfig& config) {
  const auto limit = static_cast<std::size_t>(config.max_qualifier_values_per_action_type);
  if (limit == 0) return true;
  std::vector<std::pair<std::string, std::string>> types;
  for (const auto* s : subset)
    if (std::find(types.begin(), types.end(), action_type(*s)) == types.end()) types.push_back(action_type(*s));
  for (const auto& type : types) {
    std::vector<const SalientAction*> group;
    for (const auto* s : subset)
      if (action_type(*s) == type) group.push_back(s);
    if (group.size() < 2) continue;
    std::vector<Term> seen;
    for (const auto& p : group.front()->predicates) seen.push_back(masked(p, config));
    for (std::size_t i = 1; i < group.size(); ++i)
      for (const auto& p : group[i]->predicates) {
        Term m = masked(p, config);
        if (std::find(seen.begin(), seen.end(), m) != seen.end()) continue;
        if (seen.size() >= limit) return false;
        seen.push_back(std::move(m));
      }
  }
  return true;
}

}  // namespace

std::vector<std::vector<std::size_t>> select_command_subsets(const std::vector<SalientAction>& salient,
                                                             const LanguageConfig& config) {
  Subset usable;
  for (std::size_t i = 0; i < salient.size(); ++i)
    if (config.speaker_actions != SpeakerActionRule::ExcludeAll || salient[i].agent != config.speaker)
      usable.push_back(i);

  std::vector<Subset> selected;
  const std::size_t max_size = std::min<std::size_t>(static_cast<std::size_t>(config.max_command_actions),
                                                     usable.size());
  const auto max_types = static_cast<std::size_t>(config.max_action_types);
  for (std::size_t n = 1; n <= max_size; ++n) {
    for_each_combination(usable.size(), n, [&](const Subset& combo) {
      std::vector<const SalientAction*> subset;
      Subset indices;
      for (std::size_t c : combo) {
        indices.push_back(usable[c]);
        subset.push_back(&salient[usable[c]]);
      }
      if (config.speaker_actions == SpeakerActionRule::ExcludeSpeakerOnlyCommands &&
          std::all_of(subset.begin(), subset.end(), [&](const auto* s) { return s->agent == config.speaker; }))
        return;
      // The reference applies these two rules only above the type limit
      // (n >= 3 with the defaults), where they can first fail.
      if (n > max_types) {
        std::set<std::pair<std::string, std::string>> types;
        for (const auto* s : subset) types.insert(action_type(*s));
        if (types.size() > max_types) return;
      }
      if (config.exclude_chains && has_chain(subset, config)) return;
      if (n > max_types && !qualifiers_consistent(subset, config)) return;
      selected.push_back(std::move(indices));
    });
  }
  return selected;
}

std::vector<Command> enumerate_commands(const std::vector<SalientAction>& salient, const LanguageConfig& config,
                                        const TypeLookup& type_of) {
  std::vector<Command> commands;
  for (const auto& indices : select_command_subsets(salient, config)) {
    std::vector<SalientAction> subset;
    for (std::size_t i : indices) subset.push_back(salient[i]);
    Command cmd = lift_command(subset, config, type_of);
    if (std::find(commands.begin(), commands.end(), cmd) == commands.end()) commands.push_back(std::move(cmd));
  }
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
