#include "serve/command_words.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "commands/term.hpp"
#include "lm/wordnet_lexicon.hpp"

namespace clips::serve {

using nlohmann::json;

namespace {

// "cutting-board" -> "cutting board"
std::string spaced(std::string s) {
  std::replace_if(s.begin(), s.end(), [](char c) { return c == '-' || c == '_'; }, ' ');
  return s;
}

// A variable's noun: its name without '?' and the counter ("?key1" -> key,
// "?Plate2" -> plate under qualifier-value naming).
std::string variable_noun(const std::string& var) {
  std::string n = var.substr(1);
  while (!n.empty() && std::isdigit(static_cast<unsigned char>(n.back()))) n.pop_back();
  if (!n.empty()) n.front() = static_cast<char>(std::tolower(static_cast<unsigned char>(n.front())));
  return spaced(n);
}

}  // namespace

CommandWords::CommandWords(std::shared_ptr<const pddl::Task> task, const domains::Pack& pack)
    : task_(std::move(task)), config_(pack.spec().language), qualifier_(pack.qualifier_of(*task_)) {}

std::string CommandWords::verb(const std::string& action) const {
  if (const auto it = verbs_.find(action); it != verbs_.end()) return it->second;
  std::string words = spaced(action);
  try {
    const auto phrases = lm::WordNetLexicon::instance().verb_phrases(action);
    if (!phrases.empty() && !phrases.front().empty()) words = phrases.front();
  } catch (const std::exception&) {
    // No WordNet dictionary: the name as it is, hyphens as spaces.
  }
  return verbs_[action] = words;
}

json CommandWords::steps(const std::string& display_form, bool goal_statement) const {
  std::vector<commands::Term> actions, facts;
  try {
    const size_t where = display_form.find(" where ");
    actions = commands::parse_terms(display_form.substr(0, where));
    if (where != std::string::npos) facts = commands::parse_terms(display_form.substr(where + 7));
  } catch (const std::invalid_argument&) {
    return json::array();
  }
  const pddl::Domain& domain = task_->domain();
  const auto agent_of = [&](const std::string& arg) -> std::string {
    if (arg == config_.speaker_pronoun) return config_.speaker;
    if (arg == config_.listener_pronoun) return config_.listener;
    return {};
  };
  const auto qualifiers = config_.qualifiers();
  const size_t subject = config_.qualifier_object_arg == 2 ? 1 : 0;
  const auto object = [&](const std::string& arg) {
    json o = {{"name", arg}, {"qualities", json::array()}};
    if (!commands::is_variable(arg)) {
      const std::string agent = agent_of(arg);
      const std::string name = agent.empty() ? arg : agent;
      o["name"] = name;
      o["noun"] = spaced(name);
      for (const auto& q : qualifier_(name))
        if (q.args.size() == 2) o["qualities"].push_back(q.args[0] == name ? q.args[1] : q.args[0]);
      return o;
    }
    o["noun"] = variable_noun(arg);
    for (const auto& f : facts) {
      if (f.args.size() != 2) continue;
      if (std::find(qualifiers.begin(), qualifiers.end(), f.name) != qualifiers.end()) {
        // The where clause repeats a fact per action that names the object.
        if (f.args[subject] == arg && !std::count(o["qualities"].begin(), o["qualities"].end(), f.args[1 - subject]))
          o["qualities"].push_back(f.args[1 - subject]);
      } else if (f.args[0] == arg && f.name == commands::kDestinationPredicate) {
        o["to"] = f.args[1];
      } else if (f.args[0] == arg && config_.is_location(f.name)) {
        o["from"] = f.args[1];
      }
    }
    return o;
  };
  json out = json::array();
  for (const auto& a : actions) {
    // The goal statement's own action is said by the goal's label.
    if (goal_statement && a.name == "make" && a.args.size() == 2 && a.args[0] == config_.speaker_pronoun &&
        a.args[1] == "?goal1")
      continue;
    if (domain.find_action(a.name) < 0) return json::array();  // not a command of this domain
    // The acting agent: the salient rule's argument, else the first pronoun.
    size_t agent_arg = a.args.size();
    if (const auto* rule = config_.salient_rule(a.name);
        rule && rule->agent_arg >= 1 && static_cast<size_t>(rule->agent_arg) <= a.args.size())
      agent_arg = static_cast<size_t>(rule->agent_arg - 1);
    else
      for (size_t i = 0; i < a.args.size() && agent_arg == a.args.size(); ++i)
        if (!agent_of(a.args[i]).empty()) agent_arg = i;
    const auto* rule = config_.salient_rule(a.name);
    json step = {{"agent", agent_arg < a.args.size() ? json(agent_of(a.args[agent_arg])) : json(nullptr)},
                 {"action", a.name},
                 {"verb", verb(a.name)},
                 {"objects", json::array()}};
    if (step["agent"] == "") step["agent"] = a.args[agent_arg];
    for (size_t i = 0; i < a.args.size(); ++i) {
      if (i == agent_arg) continue;
      json o = object(a.args[i]);
      // People leave unsaid what the words would not tell apart: of the
      // variables, the focal object and those with a quality or a place
      // ("hand me the red book", not "... in some room").
      const bool focal = rule && static_cast<int>(i) + 1 == rule->focal_arg;
      if (rule && !focal && commands::is_variable(a.args[i]) && o["qualities"].empty() && !o.contains("from") &&
          !o.contains("to"))
        continue;
      step["objects"].push_back(std::move(o));
    }
    out.push_back(std::move(step));
  }
  return out;
}

}  // namespace clips::serve
