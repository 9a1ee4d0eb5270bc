#include "commands/language_config.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "util/error.hpp"

namespace clips::commands {

const SalientActionRule* LanguageConfig::salient_rule(const std::string& action) const {
  for (const auto& rule : salient_actions)
    if (rule.action == action) return &rule;
  return nullptr;
}

std::vector<std::string> LanguageConfig::qualifiers() const {
  std::vector<std::string> out = {qualifier};
  out.insert(out.end(), more_qualifiers.begin(), more_qualifiers.end());
  return out;
}

bool LanguageConfig::names_place(const std::string& predicate) const {
  return predicate == kDestinationPredicate || is_location(predicate);
}

bool LanguageConfig::is_location(const std::string& predicate) const {
  return std::find(location_predicates.begin(), location_predicates.end(), predicate) != location_predicates.end();
}

bool LanguageConfig::is_qualifier(const std::string& predicate) const {
  return predicate == qualifier ||
         std::find(more_qualifiers.begin(), more_qualifiers.end(), predicate) != more_qualifiers.end();
}

std::string LanguageConfig::to_pronoun(const std::string& name) const {
  if (name == speaker) return speaker_pronoun;
  if (name == listener) return listener_pronoun;
  return name;
}

std::string LanguageConfig::to_agent_name(const std::string& arg) const {
  if (arg == speaker_pronoun) return speaker;
  if (arg == listener_pronoun) return listener;
  return arg;
}

namespace {

using nlohmann::json;

// Reads typed values and reports errors as "<file>: <key>: <problem>".
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    throw InputError(SourceLoc{source_, 0, 0}, key + ": " + why);
  }

  const json& field(const json& obj, const std::string& key, const std::string& path) const {
    if (!obj.is_object()) fail(path, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(path + "." + key, "missing");
    return *it;
  }

  std::string string(const json& value, const std::string& key) const {
    if (!value.is_string() || value.get<std::string>().empty()) fail(key, "expected a non-empty string");
    return value.get<std::string>();
  }

  int positive_int(const json& value, const std::string& key, int minimum = 1) const {
    if (!value.is_number_integer() || value.get<long long>() < minimum)
      fail(key, "expected an integer >= " + std::to_string(minimum));
    return value.get<int>();
  }

  // Rejects keys outside `known` and "comment" (free text, allowed everywhere).
  void only(const json& obj, const std::string& path, const std::set<std::string>& known) const {
    if (!obj.is_object()) fail(path, "expected an object");
    for (const auto& [key, value] : obj.items()) {
      if (key == "comment" && value.is_string()) continue;
      if (!known.contains(key)) fail(path + "." + key, "unknown key");
    }
  }

  bool boolean(const json& value, const std::string& key) const {
    if (!value.is_boolean()) fail(key, "expected true or false");
    return value.get<bool>();
  }

  template <class Enum>
  Enum choice(const json& value, const std::string& key,
              const std::vector<std::pair<std::string, Enum>>& options) const {
    std::string allowed;
    if (value.is_string())
      for (const auto& [name, e] : options)
        if (value.get<std::string>() == name) return e;
    for (const auto& [name, e] : options) allowed += (allowed.empty() ? "" : ", ") + name;
    fail(key, "expected one of: " + allowed);
  }

 private:
  std::string source_;
};

void read_party(const Reader& r, const json& value, const std::string& key, std::string& object,
                std::string& pronoun) {
  r.only(value, key, {"object", "pronoun"});
  object = r.string(r.field(value, "object", key), key + ".object");
  pronoun = r.string(r.field(value, "pronoun", key), key + ".pronoun");
}

}  // namespace

LanguageConfig parse_language_config(const std::string& json_text, const std::string& source_name) {
  json doc;
  try {
    doc = json::parse(json_text);
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a number too large
    throw InputError(SourceLoc{source_name, 0, 0}, std::string("invalid JSON: ") + e.what());
  }
  const Reader r(source_name);
  if (!doc.is_object()) r.fail("(top level)", "expected an object");

  static const std::set<std::string> known = {
      "domain", "salient_actions", "qualifier", "speaker", "listener", "max_command_actions",
      "max_action_types", "max_qualifier_values_per_action_type", "speaker_actions",
      "exclude_chains", "paper_speaker_actions", "paper_exclude_chains", "variable_naming", "printed_form", "printed_args", "goal_atoms", "goal_variables",
      "locations", "destinations", "goal_statements", "goal_with_command", "comment"};
  for (const auto& [key, value] : doc.items())
    if (!known.contains(key)) r.fail(key, "unknown key");

  LanguageConfig c;
  c.domain = r.string(r.field(doc, "domain", ""), "domain");

  const json& actions = r.field(doc, "salient_actions", "");
  if (!actions.is_array() || actions.empty()) r.fail("salient_actions", "expected a non-empty array");
  for (std::size_t i = 0; i < actions.size(); ++i) {
    const std::string key = "salient_actions[" + std::to_string(i) + "]";
    SalientActionRule rule;
    r.only(actions[i], key, {"action", "agent_arg", "focal_arg"});
    rule.action = r.string(r.field(actions[i], "action", key), key + ".action");
    if (actions[i].contains("agent_arg"))
      rule.agent_arg = r.positive_int(actions[i]["agent_arg"], key + ".agent_arg");
    rule.focal_arg = r.positive_int(r.field(actions[i], "focal_arg", key), key + ".focal_arg");
    // One rule per action: the listener reads the first, and repeats would
    // multiply the commands enumerated.
    for (std::size_t j = 0; j < c.salient_actions.size(); ++j)
      if (c.salient_actions[j].action == rule.action)
        r.fail(key + ".action", "'" + rule.action + "' is already salient_actions[" + std::to_string(j) + "]");
    c.salient_actions.push_back(rule);
  }

  if (doc.contains("qualifier")) {
    const json& q = doc["qualifier"];
    c.qualifier = r.string(r.field(q, "predicate", "qualifier"), "qualifier.predicate");
    r.only(q, "qualifier", {"predicate", "object_arg", "more"});
    if (q.contains("object_arg"))
      c.qualifier_object_arg = r.positive_int(q["object_arg"], "qualifier.object_arg");
    if (q.contains("more")) {
      const json& more = q["more"];
      if (!more.is_array()) r.fail("qualifier.more", "expected an array of predicate names");
      for (std::size_t i = 0; i < more.size(); ++i) {
        const std::string key = "qualifier.more[" + std::to_string(i) + "]";
        const std::string name = r.string(more[i], key);
        if (c.is_qualifier(name)) r.fail(key, "'" + name + "' is already a qualifier");
        c.more_qualifiers.push_back(name);
      }
    }
  }
  if (doc.contains("speaker")) read_party(r, doc["speaker"], "speaker", c.speaker, c.speaker_pronoun);
  if (doc.contains("listener"))
    read_party(r, doc["listener"], "listener", c.listener, c.listener_pronoun);
  if (doc.contains("max_command_actions")) {
    c.max_command_actions = r.positive_int(doc["max_command_actions"], "max_command_actions");
    // Commands are enumerated as sets of grounded salient actions: their
    // number grows as (actions)^k, and 5 already runs for minutes (8: out of memory).
    if (c.max_command_actions > kMaxCommandActions)
      r.fail("max_command_actions", std::to_string(c.max_command_actions) + " is more than " +
                                        std::to_string(kMaxCommandActions) +
                                        " (commands are every set of up to this many actions: larger sets "
                                        "cannot be enumerated in useful time)");
  }
  if (doc.contains("max_action_types"))
    c.max_action_types = r.positive_int(doc["max_action_types"], "max_action_types");
  if (doc.contains("max_qualifier_values_per_action_type"))
    c.max_qualifier_values_per_action_type = r.positive_int(
        doc["max_qualifier_values_per_action_type"], "max_qualifier_values_per_action_type", 0);
  auto speaker_rule = [&](const char* key) {
    return r.choice<SpeakerActionRule>(
        doc[key], key,
        {{"exclude-all", SpeakerActionRule::ExcludeAll},
         {"exclude-speaker-only-commands", SpeakerActionRule::ExcludeSpeakerOnlyCommands}});
  };
  if (doc.contains("speaker_actions")) c.speaker_actions = speaker_rule("speaker_actions");
  if (doc.contains("exclude_chains")) c.exclude_chains = r.boolean(doc["exclude_chains"], "exclude_chains");
  if (doc.contains("paper_speaker_actions")) c.paper_speaker_actions = speaker_rule("paper_speaker_actions");
  if (doc.contains("paper_exclude_chains"))
    c.paper_exclude_chains = r.boolean(doc["paper_exclude_chains"], "paper_exclude_chains");
  if (doc.contains("variable_naming"))
    c.variable_naming = r.choice<VariableNaming>(
        doc["variable_naming"], "variable_naming",
        {{"object-type", VariableNaming::ObjectType}, {"qualifier-value", VariableNaming::QualifierValue}});
  if (doc.contains("printed_form"))
    c.printed_form = r.choice<PrintedForm>(
        doc["printed_form"], "printed_form",
        {{"where-clause", PrintedForm::WhereClause},
         {"qualified-args-only", PrintedForm::QualifiedArgsOnly}});
  if (doc.contains("printed_args"))
    c.print_agents_and_focal_only =
        r.choice<bool>(doc["printed_args"], "printed_args", {{"all", false}, {"agents-and-focal", true}});
  if (doc.contains("goal_atoms")) {
    const json& atoms = doc["goal_atoms"];
    if (!atoms.is_object()) r.fail("goal_atoms", "expected an object of action -> [atom templates]");
    for (const auto& [action, templates] : atoms.items()) {
      if (action == "comment" && templates.is_string()) continue;
      const std::string key = "goal_atoms." + action;
      if (!templates.is_array() || templates.empty()) r.fail(key, "expected a non-empty array of strings");
      for (const auto& t : templates) c.goal_atoms[action].push_back(r.string(t, key));
    }
  }
  if (doc.contains("goal_statements")) {
    const json& g = doc["goal_statements"];
    if (!g.is_number() || !(g.get<double>() >= 0 && g.get<double>() < 1))
      r.fail("goal_statements", "expected a number in [0, 1)");
    c.goal_statements = g.get<double>();
  }
  if (doc.contains("goal_with_command")) {
    const json& g = doc["goal_with_command"];
    if (!g.is_number() || !(g.get<double>() >= 0 && g.get<double>() <= 1))
      r.fail("goal_with_command", "expected a number in [0, 1]");
    c.goal_with_command = g.get<double>();
  }
  if (doc.contains("destinations")) c.destinations = r.boolean(doc["destinations"], "destinations");
  if (doc.contains("locations")) {
    const json& l = doc["locations"];
    if (l.is_string()) {
      const std::string mode = l.get<std::string>();
      if (mode != "auto" && mode != "none") r.fail("locations", "expected \"auto\", \"none\" or an array of predicate names");
      c.locations_auto = mode == "auto";
    } else if (l.is_array()) {
      c.locations_auto = false;
      for (std::size_t i = 0; i < l.size(); ++i) c.location_predicates.push_back(r.string(l[i], "locations[" + std::to_string(i) + "]"));
    } else {
      r.fail("locations", "expected \"auto\", \"none\" or an array of predicate names");
    }
  }
  if (doc.contains("goal_variables"))
    c.goal_variables = r.choice<GoalVariables>(
        doc["goal_variables"], "goal_variables",
        {{"existential", GoalVariables::Existential},
         {"lowercased-name", GoalVariables::LowercasedName}});
  return c;
}

LanguageConfig load_language_config(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(SourceLoc{path.string(), 0, 0}, "cannot open language config");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_language_config(text.str(), path.string());
}

}  // namespace clips::commands
