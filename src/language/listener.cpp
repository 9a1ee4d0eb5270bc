#include "language/listener.hpp"

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "domains/dkg_world.hpp"
#include "domains/vh_world.hpp"
#include "language/commands/enumerate.hpp"
#include "language/lm/cached_model.hpp"
#include "language/lm/embedded_model.hpp"
#include "language/lm/openai_model.hpp"
#include "util/data_dir.hpp"
#include "util/error.hpp"

namespace clips::language {

namespace {

constexpr const char* kDkg = "doors-keys-gems";
constexpr const char* kVh = "virtual-home";

bool is_blank(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c) != 0; });
}

pddl::ObjectId require_object(const pddl::Task& task, const std::string& name) {
  auto o = task.find_object(name);
  if (!o) throw InputError("the problem has no object '" + name + "' (needed by the literal listener)");
  return *o;
}

// The type name the command lifting expects: key/door/gem in mDKG, item/fixture
// in VH (their variable counters are per type), else the declared type.
std::string type_name(const pddl::Task& task, pddl::ObjectId o) {
  for (const char* t : {"key", "door", "gem", "item", "fixture"})
    if (task.domain().find_type(t) && task.object_is_a(o, t)) return t;
  return task.domain().types[task.problem().objects[o].type].name;
}

commands::TypeLookup type_lookup(const pddl::Task& task) {
  return [&task](const std::string& object) {
    auto o = task.find_object(object);
    return o ? type_name(task, *o) : std::string();
  };
}

std::vector<commands::Term> dkg_candidates(const pddl::Task& task, const pddl::State& s,
                                           const commands::LanguageConfig& config) {
  const domains::DkgWorld world(task);
  const pddl::ObjectId robot = require_object(task, config.listener);
  const std::string& robot_name = task.object_name(robot);
  const std::string& human_name = task.object_name(require_object(task, config.speaker));
  // `forbidden` is the only static precondition besides colours; a robot
  // forbidden to hold an item can neither pick it up nor hand it over.
  auto forbidden = [&](pddl::ObjectId item) {
    if (!task.domain().find_predicate("forbidden")) return false;
    return task.test(s, task.atom("forbidden", {robot_name, task.object_name(item)}));
  };
  std::vector<commands::Term> out;
  for (pddl::ObjectId k : world.keys())
    if (!forbidden(k)) out.push_back({"pickup", {robot_name, world.name(k)}});
  for (pddl::ObjectId k : world.keys())
    if (!forbidden(k)) out.push_back({"handover", {robot_name, human_name, world.name(k)}});
  for (pddl::ObjectId k : world.keys())
    for (pddl::ObjectId d : world.doors())
      if (!world.color(k).empty() && world.color(k) == world.color(d))
        out.push_back({"unlock", {robot_name, world.name(k), world.name(d)}});
  return out;
}

std::vector<commands::Term> vh_candidates(const pddl::Task& task, const pddl::State& s,
                                          const commands::LanguageConfig& config) {
  const domains::VhWorld world(task);
  const std::string& helper = task.object_name(require_object(task, config.listener));
  auto by_name = [&](std::vector<pddl::ObjectId> objects) {
    std::sort(objects.begin(), objects.end(),
              [&](pddl::ObjectId a, pddl::ObjectId b) { return world.name(a) < world.name(b); });
    return objects;
  };
  std::vector<commands::Term> out;
  for (pddl::ObjectId f : by_name(world.fixtures()))
    for (pddl::ObjectId i : by_name(world.items()))
      if (world.placed(s, i, f)) out.push_back({"grab", {helper, world.name(i), world.name(f)}});
  return out;
}

}  // namespace

// ---- language-model backends ----------------------------------------------

std::vector<std::string> language_model_kinds() { return {"embedded", "openai"}; }

std::shared_ptr<lm::LanguageModel> make_language_model(const std::string& kind, const LanguageModelOptions& options) {
  std::shared_ptr<lm::LanguageModel> inner;
  if (kind.empty() || kind == "embedded") {
    lm::EmbeddedModelOptions o;
    o.data_dir = options.data_dir;
    inner = std::make_shared<lm::EmbeddedLanguageModel>(o);
  } else if (kind == "openai") {
    lm::OpenAiCompletionsOptions o;
    o.base_url = options.base_url;
    o.model = options.model;
    o.api_key = options.api_key;
    if (options.timeout_seconds > 0) {
      o.http.total_timeout = std::chrono::milliseconds(static_cast<long long>(options.timeout_seconds * 1000));
    }
    if (options.max_reply_mb > 0) o.http.max_reply_bytes = static_cast<std::size_t>(options.max_reply_mb * 1048576.0);
    inner = std::make_shared<lm::OpenAiCompletionsModel>(o);
  } else {
    throw InputError("unknown language model '" + kind + "' (known: embedded, openai)");
  }
  return std::make_shared<lm::CachedLanguageModel>(inner);
}

// ---- listener setup ---------------------------------------------------------

std::string language_data_dir() { return util::data_dir() + "/language"; }

LiteralListenerSetup literal_listener_setup(const std::string& domain, const std::string& data_dir) {
  LiteralListenerSetup setup;
  if (domain == kDkg) {
    setup.config = commands::doors_keys_gems_language();
    setup.temperature = 1.0;
  } else if (domain == kVh) {
    setup.config = commands::virtual_home_language();
    setup.temperature = 0.5;
  } else {
    throw InputError("the literal listener knows no domain '" + domain + "' (known: " + kDkg + ", " + kVh + ")");
  }
  const std::string dir = data_dir.empty() ? language_data_dir() : data_dir;
  const auto examples = commands::load_fewshot_examples(dir + "/fewshot-examples.tsv");
  const auto orders = commands::load_prompt_orders(dir + "/prompt-orders.json");
  const auto it = orders.find(domain);
  if (it == orders.end()) throw InputError(dir + "/prompt-orders.json: no prompt orders for '" + domain + "'");
  setup.examples = commands::order_examples(examples, domain, it->second.literal);
  return setup;
}

std::string language_domain_of(const pddl::Task& task) {
  const auto& d = task.domain();
  if (d.find_type("key") && d.find_type("door")) return kDkg;
  if (d.find_type("item") && d.find_type("fixture")) return kVh;
  throw InputError("domain '" + d.name + "' is neither doors-keys-gems nor virtual-home: no literal listener");
}

// ---- candidates and commands --------------------------------------------------

std::vector<commands::Term> literal_candidate_actions(const pddl::Task& task, const pddl::State& s,
                                                      const commands::LanguageConfig& config) {
  if (config.domain == kDkg) return dkg_candidates(task, s, config);
  if (config.domain == kVh) return vh_candidates(task, s, config);
  throw InputError("the literal listener knows no domain '" + config.domain + "'");
}

std::vector<commands::Command> literal_commands(const pddl::Task& task, const pddl::State& s,
                                                const commands::LanguageConfig& config) {
  const auto candidates = literal_candidate_actions(task, s, config);
  // Qualifiers (colours, item types) are static facts of the problem, so they
  // are looked up in the task rather than the state.
  commands::QualifierLookup qualifier_of;
  if (config.domain == kDkg) {
    auto world = std::make_shared<domains::DkgWorld>(task);
    qualifier_of = [world, &task, &config](const std::string& object) -> std::optional<commands::Term> {
      auto o = task.find_object(object);
      if (!o || world->color(*o).empty()) return std::nullopt;
      return commands::Term{config.qualifier, {object, world->color(*o)}};
    };
  } else {
    auto world = std::make_shared<domains::VhWorld>(task);
    qualifier_of = [world, &task, &config](const std::string& object) -> std::optional<commands::Term> {
      auto o = task.find_object(object);
      if (!o || !task.object_is_a(*o, "item")) return std::nullopt;
      const std::string type = world->item_type(*o);
      if (type.empty()) return std::nullopt;
      return commands::Term{config.qualifier, {object, type}};
    };
  }
  return commands::enumerate_literal_candidates(candidates, config, qualifier_of, type_lookup(task));
}

// ---- scoring ------------------------------------------------------------------

ListenerResult rank_commands(const std::vector<commands::Command>& commands, const std::string& utterance,
                             const LiteralListenerSetup& setup, lm::LanguageModel& lm) {
  if (is_blank(utterance)) throw InputError("--utterance is empty");
  if (!(setup.temperature > 0)) throw InputError("listener temperature must be positive");
  ListenerResult result;
  result.utterance = utterance;
  if (commands.empty()) return result;

  const std::string continuation = commands::utterance_continuation(utterance);
  std::vector<lm::ScoreRequest> batch;
  batch.reserve(commands.size());
  for (const auto& c : commands) batch.push_back({commands::build_prompt(setup.examples, c.llm_form()), continuation});
  const std::vector<double> scores = lm.score(batch);
  if (scores.size() != commands.size())
    throw lm::LmError(lm.name() + ": returned " + std::to_string(scores.size()) + " scores for " +
                      std::to_string(commands.size()) + " prompts");

  result.commands.reserve(commands.size());
  double best = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < commands.size(); ++i) {
    const double ll = scores[i] / setup.temperature;
    result.commands.push_back({commands[i], ll, 0.0});
    best = std::max(best, ll);
  }
  // Softmax with the maximum subtracted. If every score is -inf the utterance
  // is impossible under all commands; the uniform prior is then the posterior.
  if (std::isinf(best) && best < 0) {
    for (auto& r : result.commands) r.prob = 1.0 / static_cast<double>(commands.size());
  } else {
    double total = 0;
    for (auto& r : result.commands) total += (r.prob = std::exp(r.log_likelihood - best));
    for (auto& r : result.commands) r.prob /= total;
  }
  std::stable_sort(result.commands.begin(), result.commands.end(),
                   [](const RankedCommand& a, const RankedCommand& b) { return a.prob > b.prob; });
  return result;
}

ListenerResult literal_listener(const pddl::Task& task, const pddl::State& s, const std::string& utterance,
                                const LiteralListenerSetup& setup, lm::LanguageModel& lm) {
  // Check the utterance before the (possibly large) enumeration.
  if (is_blank(utterance)) throw InputError("--utterance is empty");
  return rank_commands(literal_commands(task, s, setup.config), utterance, setup, lm);
}

// ---- commands as goals ----------------------------------------------------------

pddl::CompiledCondition compile_command_goal(const pddl::Task& task, const commands::Command& command,
                                  const commands::LanguageConfig& config) {
  const std::string formula = command.to_goal_formula(config);
  return task.compile_text(formula, "<goal of " + command.display_form() + ">");
}

pddl::State completed_final_state(const pddl::Task& task, const pddl::PlanFile& observed,
                                  const pddl::PlanFile& completed) {
  const pddl::State end_of_observed = pddl::simulate(task, task.initial_state(), observed).states.back();
  return pddl::simulate(task, end_of_observed, completed).states.back();
}

bool state_satisfies_command(const pddl::Task& task, const pddl::State& state, const commands::Command& command,
                             const commands::LanguageConfig& config) {
  return compile_command_goal(task, command, config).holds(state);
}

pddl::State achieved_facts(const pddl::Task& task, const std::vector<pddl::State>& states) {
  if (states.empty()) throw std::invalid_argument("achieved_facts: no states");
  pddl::State out = states.back();
  // Only the atom words are OR-ed: the words after fluent_base() pack int16
  // fluent values, which must not be mixed bitwise.
  for (const auto& s : states)
    for (int w = 0; w < task.fluent_base(); ++w) out.words[w] |= s.words[w];
  return out;
}

bool completed_plan_satisfies(const pddl::Task& task, const pddl::PlanFile& observed, const pddl::PlanFile& completed,
                              const commands::Command& command, const commands::LanguageConfig& config) {
  const pddl::State s_T = pddl::simulate(task, task.initial_state(), observed).states.back();
  return state_satisfies_command(task, achieved_facts(task, pddl::simulate(task, s_T, completed).states), command,
                                 config);
}

}  // namespace clips::language
