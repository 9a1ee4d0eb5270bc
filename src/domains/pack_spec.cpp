// Reading pack.json into a PackSpec. Every field is optional except "domain";
// unknown fields and bad values are errors naming the file and the field.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "domains/pack.hpp"
#include "pddl/sexpr.hpp"
#include "util/data_dir.hpp"
#include "util/error.hpp"
#include "util/json_schema.hpp"

namespace clips::domains {

namespace {

using nlohmann::json;

class Fields {
 public:
  explicit Fields(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& why) const {
    throw InputError(SourceLoc{source_, 0, 0}, field + ": " + why);
  }
  // Rejects keys outside `known` (a misspelt field would otherwise be ignored).
  void only(const json& obj, const std::string& path, const std::set<std::string>& known) const {
    if (!obj.is_object()) fail(path.empty() ? "(top level)" : path, "expected an object");
    for (const auto& [key, value] : obj.items()) {
      if (key == "comment" && !value.is_string()) fail(join(path, key), "expected a string (free text)");
      if (!known.contains(key)) {
        std::string list;
        for (const auto& k : known)
          if (k != "comment" && k != "$schema") list += (list.empty() ? "" : ", ") + k;
        fail(join(path, key), "unknown field (known: " + list + ")");
      }
    }
  }
  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }
  std::string text(const json& v, const std::string& field, bool allow_empty = false) const {
    if (!v.is_string() || (!allow_empty && v.get<std::string>().empty()))
      fail(field, allow_empty ? "expected a string" : "expected a non-empty string");
    return v.get<std::string>();
  }
  int integer(const json& v, const std::string& field, long long lo, long long hi) const {
    if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
      fail(field, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
    return static_cast<int>(v.get<long long>());
  }
  double number(const json& v, const std::string& field, double lo, bool lo_open,
                double hi = std::numeric_limits<double>::infinity()) const {
    if (!v.is_number()) fail(field, "expected a number");
    const double x = v.get<double>();
    if (!(lo_open ? x > lo : x >= lo) || !std::isfinite(x) || x > hi)
      fail(field, "expected a finite number " + std::string(lo_open ? "> " : ">= ") + fmt_number(lo) +
                      (std::isfinite(hi) ? " and <= " + fmt_number(hi) : "") + ", got " + v.dump());
    return x;
  }
  static std::string fmt_number(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
  }
  bool boolean(const json& v, const std::string& field) const {
    if (!v.is_boolean()) fail(field, "expected true or false");
    return v.get<bool>();
  }
  std::vector<std::string> strings(const json& v, const std::string& field) const {
    if (!v.is_array()) fail(field, "expected an array of strings");
    std::vector<std::string> out;
    for (size_t i = 0; i < v.size(); ++i) out.push_back(text(v[i], field + "[" + std::to_string(i) + "]"));
    return out;
  }
  std::vector<int> indices(const json& v, const std::string& field) const {
    if (!v.is_array()) fail(field, "expected an array of integers");
    std::vector<int> out;
    for (size_t i = 0; i < v.size(); ++i) out.push_back(integer(v[i], field + "[" + std::to_string(i) + "]", 0, 1 << 30));
    return out;
  }
  template <class E>
  E choice(const json& v, const std::string& field, const std::vector<std::pair<const char*, E>>& options) const {
    if (v.is_string())
      for (const auto& [name, e] : options)
        if (v.get<std::string>() == name) return e;
    std::string allowed;
    for (const auto& [name, e] : options) allowed += (allowed.empty() ? "" : ", ") + std::string(name);
    fail(field, "expected one of: " + allowed);
  }
  // A name of a name table (util/choices.hpp), its older spellings too.
  template <typename E>
  E choice(const json& v, const std::string& field, const util::Choices<E>& table) const {
    if (v.is_string() && table.contains(v.get<std::string>())) return table.parse(v.get<std::string>());
    std::string allowed;
    for (const std::string& name : table.names()) allowed += (allowed.empty() ? "" : ", ") + name;
    fail(field, "expected one of: " + allowed);
  }
  const std::string& source() const { return source_; }

 private:
  std::string source_;
};

// The largest cost a profile may give an action.
constexpr double kMaxActionCost = 1e6;
// The most cost profiles one rule may list (the paper's domains have 2 or 3).
constexpr size_t kMaxProfilesPerRule = 32;

model::CostProfile read_profile(const Fields& f, const json& v, const std::string& path) {
  f.only(v, path, {"name", "default", "costs", "comment"});
  model::CostProfile p;
  if (!v.contains("name")) f.fail(path + ".name", "missing");
  p.name = f.text(v["name"], path + ".name");
  // Costs are exponentiated in the Boltzmann policies: beyond kMaxActionCost
  // every likelihood underflows to 0 (a uniform posterior, -inf log
  // marginal). A default of 0 makes every unlisted action free, and plans
  // with free detours never end: the default must be > 0.
  if (v.contains("default")) p.default_cost = f.number(v["default"], path + ".default", 0, true, kMaxActionCost);
  if (v.contains("costs")) {
    const json& c = v["costs"];
    if (!c.is_object()) f.fail(path + ".costs", "expected an object {\"<agent>\": {\"<action>\": cost}}");
    for (const auto& [agent, actions] : c.items()) {
      const std::string ap = path + ".costs." + agent;
      if (agent == "comment" && actions.is_string()) continue;
      if (!actions.is_object()) f.fail(ap, "expected an object {\"<action>\": cost}");
      for (const auto& [action, cost] : actions.items())
        if (action != "comment" || !cost.is_string()) p.costs[{agent, action}] = f.number(cost, ap + "." + action, 0, false, kMaxActionCost);
    }
  }
  return p;
}

}  // namespace

util::Choices<LiteralPlanning>& literal_method_choices() {
  static util::Choices<LiteralPlanning> table(
      "literal listener method",
      {{LiteralPlanning::Efficient, "literal_efficient", "the literal listener, planning for a command as a lifted goal",
        {}},
       {LiteralPlanning::Naive, "literal_naive", "the literal listener, planning for a command's groundings one by one",
        {}},
       {LiteralPlanning::Efficient, "literal", "literal_efficient, under the name VirtualHome's results use", {}}});
  return table;
}

util::Choices<RolloutSettings::Plans>& speaker_plans_choices() {
  static util::Choices<RolloutSettings::Plans> table(
      "speaker plans",
      {{RolloutSettings::Plans::Tied, "tied",
        "every joint plan the policy values as well as its greedy one, ties broken every way", {}},
       {RolloutSettings::Plans::Single, "single", "the one greedy rollout, as in the paper's tables", {}}});
  return table;
}

PackSpec parse_pack_spec(const std::string& json_text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(json_text);
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a number too large
    throw InputError(SourceLoc{source, 0, 0}, std::string("invalid JSON: ") + e.what());
  }
  const Fields f(source);
  f.only(doc, "",
         {"domain", "code", "grounding", "roles", "goals", "cost_profiles", "default_cost_profile", "inference", "language", "fewshot",
          "literal_listener", "assistance_options", "max_utterances_per_plan", "plan_tags", "scene", "scene_colours", "rules_text",
          "embedded_corpus", "assistance_rule", "comment", "$schema"});
  PackSpec s;
  s.source = source;
  if (!doc.contains("domain")) f.fail("domain", "missing (the PDDL domain name the pack is for)");
  s.name = f.text(doc["domain"], "domain");
  if (doc.contains("code")) s.code = f.text(doc["code"], "code", true);
  if (doc.contains("$schema")) f.text(doc["$schema"], "$schema");  // for editors (data/schema/pack.schema.json)
  s.grounding.keep_dynamic = {"frozen", "nograb", "noput"};

  if (doc.contains("grounding")) {
    const json& g = doc["grounding"];
    f.only(g, "grounding", {"keep_dynamic", "schema_order", "first_param_fastest", "objects_by_name", "comment"});
    if (g.contains("keep_dynamic"))
      for (auto& p : f.strings(g["keep_dynamic"], "grounding.keep_dynamic")) s.grounding.keep_dynamic.insert(p);
    if (g.contains("schema_order")) s.grounding.schema_order = f.strings(g["schema_order"], "grounding.schema_order");
    if (g.contains("first_param_fastest"))
      s.grounding.first_param_fastest = f.boolean(g["first_param_fastest"], "grounding.first_param_fastest");
    if (g.contains("objects_by_name"))
      s.grounding.objects_by_name = f.boolean(g["objects_by_name"], "grounding.objects_by_name");
  }

  if (doc.contains("roles")) {
    const json& r = doc["roles"];
    f.only(r, "roles", {"principal", "assistant", "noop_action", "turn_predicate", "turns", "agent_type", "horizon",
                        "noop_cost", "principal_effort", "principal_follows_completed_plan", "comment"});
    if (r.contains("principal")) s.roles.principal = f.text(r["principal"], "roles.principal");
    if (r.contains("assistant")) s.roles.assistant = f.text(r["assistant"], "roles.assistant");
    if (r.contains("noop_action")) s.roles.noop_action = f.text(r["noop_action"], "roles.noop_action");
    if (r.contains("turn_predicate")) s.roles.turn_predicate = f.text(r["turn_predicate"], "roles.turn_predicate");
    if (r.contains("agent_type")) s.roles.agent_type = f.text(r["agent_type"], "roles.agent_type");
    if (r.contains("turns")) {
      const json& t = r["turns"];
      if (t.is_array()) {
        s.roles.turns = TurnMode::Order;
        s.roles.turn_order = f.strings(t, "roles.turns");
        if (s.roles.turn_order.size() < 2)
          f.fail("roles.turns", "expected at least two agents in turn order (the principal and the assistant)");
        for (size_t i = 0; i < s.roles.turn_order.size(); ++i)
          for (size_t j = 0; j < i; ++j)
            if (s.roles.turn_order[i] == s.roles.turn_order[j])
              f.fail("roles.turns[" + std::to_string(i) + "]", "'" + s.roles.turn_order[i] + "' is listed twice");
      } else if (t.is_string() && (t == "domain" || t == "alternate")) {
        s.roles.turns = t == "domain" ? TurnMode::Domain : TurnMode::Alternate;
      } else {
        f.fail("roles.turns", "expected \"domain\", \"alternate\" or an array of agent object names in turn order");
      }
    }
    if (r.contains("horizon")) s.roles.horizon = f.integer(r["horizon"], "roles.horizon", 1, 100000);
    if (r.contains("noop_cost")) s.roles.noop_cost = f.number(r["noop_cost"], "roles.noop_cost", 0, false);
    if (r.contains("principal_effort"))
      s.roles.principal_effort = f.number(r["principal_effort"], "roles.principal_effort", 0, true, 1000);
    if (r.contains("principal_follows_completed_plan"))
      s.roles.principal_follows_completed_plan =
          f.boolean(r["principal_follows_completed_plan"], "roles.principal_follows_completed_plan");
  }
  if (s.roles.principal == s.roles.assistant) f.fail("roles.assistant", "must differ from roles.principal");
  if (s.roles.turns == TurnMode::Order)
    for (const std::string* who : {&s.roles.principal, &s.roles.assistant})
      if (std::find(s.roles.turn_order.begin(), s.roles.turn_order.end(), *who) == s.roles.turn_order.end())
        f.fail("roles.turns", "the turn order must include " +
                                  std::string(who == &s.roles.principal ? "roles.principal" : "roles.assistant") +
                                  " '" + *who + "'");

  if (doc.contains("goals")) {
    const json& g = doc["goals"];
    f.only(g, "goals", {"source", "object_type", "condition", "true_goal", "comment"});
    if (g.contains("source"))
      s.goals.source = f.choice<GoalSource>(g["source"], "goals.source",
                                            {{"goal-sets", GoalSource::GoalSets},
                                             {"objects", GoalSource::Objects},
                                             {"problem-goal", GoalSource::ProblemGoal}});
    if (g.contains("object_type")) s.goals.object_type = f.text(g["object_type"], "goals.object_type");
    if (g.contains("condition")) s.goals.condition = f.text(g["condition"], "goals.condition");
    if (s.goals.source == GoalSource::Objects) {
      if (s.goals.object_type.empty()) f.fail("goals.object_type", "missing (needed by source \"objects\")");
      if (s.goals.condition.find("{}") == std::string::npos)
        f.fail("goals.condition", "needs a condition template with {} for the object, e.g. \"(has human {})\"");
    }
    // Where goals are labelled (goal sets), plans name their goal; otherwise
    // the completion says which goal it reached.
    s.goals.true_goal = s.goals.source == GoalSource::GoalSets ? TrueGoalRule::PlanTag : TrueGoalRule::CompletionReaches;
    if (g.contains("true_goal"))
      s.goals.true_goal = f.choice<TrueGoalRule>(g["true_goal"], "goals.true_goal",
                                                 {{"plan-tag", TrueGoalRule::PlanTag},
                                                  {"completion-reaches", TrueGoalRule::CompletionReaches},
                                                  {"last-action-object", TrueGoalRule::LastActionObject}});
  }

  if (doc.contains("cost_profiles")) {
    const json& c = doc["cost_profiles"];
    if (!c.is_array() || c.empty()) f.fail("cost_profiles", "expected a non-empty array of {tag, profiles, true_index}");
    for (size_t i = 0; i < c.size(); ++i) {
      const std::string path = "cost_profiles[" + std::to_string(i) + "]";
      f.only(c[i], path, {"tag", "profiles", "true_index", "comment"});
      ProfileRule rule;
      if (c[i].contains("tag")) rule.tag = f.text(c[i]["tag"], path + ".tag", true);
      if (!c[i].contains("profiles") || !c[i]["profiles"].is_array() || c[i]["profiles"].empty())
        f.fail(path + ".profiles", "expected a non-empty array of profiles");
      // Every profile is one more hypothesis per goal, searched at every step.
      if (c[i]["profiles"].size() > kMaxProfilesPerRule)
        f.fail(path + ".profiles", std::to_string(c[i]["profiles"].size()) + " profiles; at most " +
                                       std::to_string(kMaxProfilesPerRule) +
                                       " (each is one more hypothesis per goal to plan for at every step)");
      for (size_t k = 0; k < c[i]["profiles"].size(); ++k) {
        const std::string at = path + ".profiles[" + std::to_string(k) + "]";
        rule.profiles.push_back(read_profile(f, c[i]["profiles"][k], at));
        for (size_t e = 0; e + 1 < rule.profiles.size(); ++e)
          if (rule.profiles[e].name == rule.profiles.back().name)
            f.fail(at + ".name", "\"" + rule.profiles.back().name + "\" is also the name of profiles[" +
                                     std::to_string(e) + "]");
      }
      if (c[i].contains("true_index"))
        rule.true_index = f.integer(c[i]["true_index"], path + ".true_index", 0,
                                    static_cast<long long>(rule.profiles.size()) - 1);
      for (const auto& earlier : s.cost_profiles)
        if (earlier.tag == rule.tag) f.fail(path + ".tag", "a second rule for tag \"" + rule.tag + "\"");
      s.cost_profiles.push_back(std::move(rule));
    }
  }

  if (doc.contains("default_cost_profile"))
    s.default_cost_profile = f.text(doc["default_cost_profile"], "default_cost_profile");

  if (doc.contains("inference")) {
    const json& in = doc["inference"];
    f.only(in, "inference", {"heuristic", "search", "temperature_prior", "rollout", "utterance_noise", "utterance_exponent",
                          "alone_cost_factor", "speaker_delegates", "request_plans", "sparing_plans", "progress_share",
                          "comment"});
    if (in.contains("request_plans")) {
      s.inference.request_plans = f.number(in["request_plans"], "inference.request_plans", 0, false);
      if (s.inference.request_plans >= 1) f.fail("inference.request_plans", "expected a number below 1");
    }
    if (in.contains("sparing_plans")) {
      s.inference.sparing_plans = f.number(in["sparing_plans"], "inference.sparing_plans", 0, false);
      if (s.inference.sparing_plans >= 1) f.fail("inference.sparing_plans", "expected a number below 1");
    }
    if (in.contains("progress_share")) {
      s.inference.progress_share = f.number(in["progress_share"], "inference.progress_share", 0, false);
      if (s.inference.progress_share >= 1) f.fail("inference.progress_share", "expected a number below 1");
    }
    if (in.contains("speaker_delegates")) {
      s.inference.speaker_delegates = f.number(in["speaker_delegates"], "inference.speaker_delegates", 0, false);
      if (s.inference.speaker_delegates >= 1) f.fail("inference.speaker_delegates", "expected a number below 1");
    }
    if (in.contains("alone_cost_factor")) {
      s.inference.alone_cost_factor = f.number(in["alone_cost_factor"], "inference.alone_cost_factor", 0, false);
      if (s.inference.alone_cost_factor != 0 &&
          !(s.inference.alone_cost_factor >= 1 && s.inference.alone_cost_factor <= 1000))
        f.fail("inference.alone_cost_factor", "expected 0 (no alone twins) or a number from 1 to 1000");
    }
    if (in.contains("utterance_noise")) {
      s.inference.utterance_noise = f.number(in["utterance_noise"], "inference.utterance_noise", 0, false);
      if (s.inference.utterance_noise >= 1) f.fail("inference.utterance_noise", "expected a number below 1");
    }
    if (in.contains("utterance_exponent")) {
      s.inference.utterance_exponent = f.number(in["utterance_exponent"], "inference.utterance_exponent", 0, false);
      if (!(s.inference.utterance_exponent > 0 && s.inference.utterance_exponent <= 10))
        f.fail("inference.utterance_exponent", "expected a number above 0 and at most 10");
    }
    if (in.contains("heuristic")) s.inference.heuristic = f.text(in["heuristic"], "inference.heuristic");
    if (in.contains("search")) s.inference.search = f.boolean(in["search"], "inference.search");
    if (in.contains("temperature_prior")) {
      const json& t = in["temperature_prior"];
      f.only(t, "inference.temperature_prior", {"shape", "scale", "comment"});
      if (t.contains("shape"))
        s.inference.temperature_shape = f.number(t["shape"], "inference.temperature_prior.shape", 0, true);
      if (t.contains("scale"))
        s.inference.temperature_scale = f.number(t["scale"], "inference.temperature_prior.scale", 0, true);
    }
    if (in.contains("rollout")) {
      const json& r = in["rollout"];
      f.only(r, "inference.rollout", {"kind", "speaker_flag", "plans", "comment"});
      if (r.contains("kind"))
        s.inference.rollout.kind = f.choice<RolloutSettings::Kind>(
            r["kind"], "inference.rollout.kind",
            {{"greedy", RolloutSettings::Kind::Greedy}, {"weighted-astar", RolloutSettings::Kind::WeightedAStar}});
      if (r.contains("speaker_flag"))
        s.inference.rollout.speaker_flag = f.text(r["speaker_flag"], "inference.rollout.speaker_flag");
      if (r.contains("plans"))
        s.inference.rollout.plans = f.choice(r["plans"], "inference.rollout.plans", speaker_plans_choices());
    }
  }

  // The language block is the command model's own format (language_config.hpp).
  s.language = commands::LanguageConfig{};
  s.language.domain = s.name;
  s.language.speaker = s.roles.principal;
  s.language.listener = s.roles.assistant;
  if (doc.contains("language")) {
    json lang = doc["language"];
    if (!lang.is_object()) f.fail("language", "expected an object");
    if (lang.contains("domain")) f.fail("language.domain", "not allowed here (the pack's \"domain\" is used)");
    lang["domain"] = s.name;
    if (!lang.contains("speaker")) lang["speaker"] = {{"object", s.roles.principal}, {"pronoun", "me"}};
    if (!lang.contains("listener")) lang["listener"] = {{"object", s.roles.assistant}, {"pronoun", "you"}};
    try {
      s.language = commands::parse_language_config(lang.dump(), source);
    } catch (const InputError& e) {
      // Its messages name the key inside the block; say which block.
      std::string what = e.what();
      const std::string prefix = source + ": ";
      if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
      f.fail("language", what);
    }
    if (s.language.speaker != s.roles.principal)
      f.fail("language.speaker.object", "\"" + s.language.speaker + "\" differs from roles.principal \"" +
                                            s.roles.principal + "\"");
    if (s.language.listener != s.roles.assistant)
      f.fail("language.listener.object", "\"" + s.language.listener + "\" differs from roles.assistant \"" +
                                             s.roles.assistant + "\"");
  }

  if (doc.contains("fewshot")) {
    const json& fs = doc["fewshot"];
    f.only(fs, "fewshot", {"file", "domain", "pragmatic_order", "literal_order", "comment"});
    if (fs.contains("file")) s.fewshot.file = f.text(fs["file"], "fewshot.file");
    if (fs.contains("domain")) s.fewshot.domain = f.text(fs["domain"], "fewshot.domain");
    if (fs.contains("pragmatic_order")) s.fewshot.pragmatic_order = f.indices(fs["pragmatic_order"], "fewshot.pragmatic_order");
    if (fs.contains("literal_order")) s.fewshot.literal_order = f.indices(fs["literal_order"], "fewshot.literal_order");
  }
  if (s.fewshot.domain.empty()) s.fewshot.domain = s.name;

  if (doc.contains("literal_listener")) {
    const json& l = doc["literal_listener"];
    f.only(l, "literal_listener", {"enabled", "temperature", "methods", "planning_heuristic", "variable_types", "comment"});
    if (l.contains("variable_types"))
      s.literal.variable_types = f.strings(l["variable_types"], "literal_listener.variable_types");
    if (l.contains("planning_heuristic"))
      s.literal.planning_heuristic = f.text(l["planning_heuristic"], "literal_listener.planning_heuristic");
    if (l.contains("enabled")) s.literal.enabled = f.boolean(l["enabled"], "literal_listener.enabled");
    if (l.contains("temperature"))
      s.literal.temperature = f.number(l["temperature"], "literal_listener.temperature", 0, true);
    if (l.contains("methods")) {
      s.literal.methods = f.strings(l["methods"], "literal_listener.methods");
      for (size_t i = 0; i < s.literal.methods.size(); ++i) {
        const auto& m = s.literal.methods[i];
        if (!literal_method_choices().contains(m))
          f.fail("literal_listener.methods[" + std::to_string(i) + "]",
                 "expected " + literal_method_choices().name_list() + ", got \"" + m + "\"");
      }
    }
  }

  if (doc.contains("assistance_options")) {
    const json& o = doc["assistance_options"];
    if (!o.is_array()) f.fail("assistance_options", "expected an array of {action, object_arg, object_type, tag}");
    for (size_t i = 0; i < o.size(); ++i) {
      const std::string path = "assistance_options[" + std::to_string(i) + "]";
      f.only(o[i], path, {"action", "object_arg", "object_type", "tag", "comment"});
      OptionRule r;
      if (!o[i].contains("action")) f.fail(path + ".action", "missing");
      r.action = f.text(o[i]["action"], path + ".action");
      if (!o[i].contains("object_arg")) f.fail(path + ".object_arg", "missing (1-based argument position)");
      r.object_arg = f.integer(o[i]["object_arg"], path + ".object_arg", 2, 64);
      if (o[i].contains("object_type")) r.object_type = f.text(o[i]["object_type"], path + ".object_type");
      if (o[i].contains("tag")) r.tag = f.text(o[i]["tag"], path + ".tag", true);
      s.options.push_back(r);
    }
  }
  if (doc.contains("assistance_rule"))
    s.assistance_rule = f.choice<std::string>(doc["assistance_rule"], "assistance_rule",
                                              {{"request", "request"}, {"paper", "paper"}});
  if (doc.contains("max_utterances_per_plan"))
    s.max_utterances_per_plan = f.integer(doc["max_utterances_per_plan"], "max_utterances_per_plan", 0, 1 << 20);
  if (doc.contains("plan_tags")) s.plan_tags = f.strings(doc["plan_tags"], "plan_tags");
  if (doc.contains("scene"))
    s.scene = f.choice<SceneKind>(doc["scene"], "scene",
                                  {{"text", SceneKind::Text}, {"grid", SceneKind::Grid}, {"cards", SceneKind::Cards}});
  if (doc.contains("scene_colours")) {
    const json& c = doc["scene_colours"];
    if (!c.is_object()) f.fail("scene_colours", "expected an object {\"<type>\": \"#rrggbb\"}");
    for (const auto& [type, value] : c.items()) {
      const std::string path = "scene_colours." + type;
      if (type == "comment") continue;
      const std::string hex = f.text(value, path);
      const bool ok = hex.size() == 7 && hex[0] == '#' &&
                      std::all_of(hex.begin() + 1, hex.end(), [](char ch) { return std::isxdigit(static_cast<unsigned char>(ch)); });
      if (!ok) f.fail(path, "expected a colour \"#rrggbb\", got \"" + hex + "\"");
      if (type.empty() || std::isdigit(static_cast<unsigned char>(type.back())))
        f.fail(path, "a type is a name without trailing digits (\"plate\" colours plate1, plate2, ...)");
      s.scene_colours[type] = hex;
    }
  }
  if (doc.contains("rules_text")) s.rules_text = f.text(doc["rules_text"], "rules_text");
  if (doc.contains("embedded_corpus")) s.embedded_corpus = f.strings(doc["embedded_corpus"], "embedded_corpus");
  return s;
}

std::string pack_schema_path() { return util::data_dir() + "/schema/pack.schema.json"; }

std::vector<std::string> pack_schema_errors(const std::string& json_text, const std::string& source,
                                            const std::string& schema_path) {
  json doc;
  try {
    doc = json::parse(json_text);
  } catch (const json::exception& e) {
    throw InputError(SourceLoc{source, 0, 0}, std::string("invalid JSON: ") + e.what());
  }
  // Read once per schema file: validate checks one pack, tests many.
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const util::JsonSchema>> loaded;
  std::shared_ptr<const util::JsonSchema> schema;
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto& slot = loaded[schema_path];
    if (!slot) slot = std::make_shared<const util::JsonSchema>(util::JsonSchema::load(schema_path));
    schema = slot;
  }
  std::vector<std::string> out;
  for (const auto& e : schema->validate(doc)) out.push_back(e.str());
  return out;
}

PackSpec load_pack_spec(const std::string& path) {
  // A regular file only (a FIFO would block, /dev/zero never end).
  return parse_pack_spec(pddl::read_text_file(path), path);
}

std::string to_string(GoalSource s) {
  switch (s) {
    case GoalSource::GoalSets: return "goal-sets";
    case GoalSource::Objects: return "objects";
    case GoalSource::ProblemGoal: return "problem-goal";
  }
  return "?";
}

std::string to_string(SceneKind s) {
  switch (s) {
    case SceneKind::Text: return "text";
    case SceneKind::Grid: return "grid";
    case SceneKind::Cards: return "cards";
  }
  return "?";
}

}  // namespace clips::domains
