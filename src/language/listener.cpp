#include "language/listener.hpp"

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <set>

#include "commands/enumerate.hpp"
#include "domains/builtin/packs.hpp"
#include "language/lm_domain.hpp"
#include "lm/cached_model.hpp"
#include "lm/embedded_model.hpp"
#include "lm/openai_model.hpp"
#include "pddl/parser.hpp"
#include "util/data_dir.hpp"
#include "util/error.hpp"
#include "util/numbered_names.hpp"

namespace clips::language {

namespace {

bool is_blank(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c) != 0; });
}

// The type name the command lifting expects (variable counters are per
// type): the first of the pack's variable types the object belongs to
// (mDKG key/door/gem, VH item/fixture), else its declared type.
std::string type_name(const pddl::Task& task, const domains::Pack& pack, pddl::ObjectId o) {
  for (const auto& t : pack.spec().literal.variable_types)
    if (task.domain().find_type(t) && task.object_is_a(o, t)) return t;
  return task.domain().types[task.problem().objects[o].type].name;
}

commands::TypeLookup type_lookup(const pddl::Task& task, const domains::Pack& pack) {
  return [&task, &pack](const std::string& object) {
    auto o = task.find_object(object);
    return o ? type_name(task, pack, *o) : std::string();
  };
}

}  // namespace

// ---- language-model backends ----------------------------------------------

util::Choices<LanguageModelKind>& language_model_choices() {
  static util::Choices<LanguageModelKind> table(
      "language model",
      {{LanguageModelKind::Embedded, "embedded", "offline: an alignment model trained at load time on the shipped corpus and the prompt's examples", {}},
       {LanguageModelKind::OpenAi, "openai", "an OpenAI-compatible completions server that scores the text, at --lm-base-url", {}}});
  return table;
}
std::vector<std::string> language_model_kinds() { return language_model_choices().names(); }

namespace {

lm::OpenAiCompletionsOptions openai_options(const LanguageModelOptions& options) {
  lm::OpenAiCompletionsOptions o;
  o.base_url = options.base_url;
  o.model = options.model;
  o.api_key = options.api_key;
  if (options.timeout_seconds > 0) {
    // Rounded up: a timeout below a millisecond must not become 0, which libcurl reads as "none".
    o.http.total_timeout = std::chrono::milliseconds(
        std::max(1LL, static_cast<long long>(std::ceil(std::min(options.timeout_seconds, 1e9) * 1000))));
  }
  if (options.max_reply_mb > 0) o.http.max_reply_bytes = static_cast<std::size_t>(options.max_reply_mb * 1048576.0);
  if (options.batch_size > 0) o.batch_size = options.batch_size;
  o.single_prompt = options.single_prompt;
  o.prompt_logprobs = options.prompt_logprobs;
  o.try_max_tokens_zero = !options.max_tokens_one;
  return o;
}

}  // namespace

ServerCheck check_language_model_server(const LanguageModelOptions& options) {
  lm::OpenAiCompletionsModel model(openai_options(options));
  const lm::ScoringCheck check = model.check_scoring();
  if (!check.can_score) throw lm::LmError(check.line);
  ServerCheck out{check.line, options};
  out.options.single_prompt = model.single_prompt();
  out.options.prompt_logprobs = model.using_prompt_logprobs();
  out.options.max_tokens_one = model.using_max_tokens_fallback();
  return out;
}

std::shared_ptr<lm::LanguageModel> make_language_model(const std::string& kind, const LanguageModelOptions& options) {
  std::shared_ptr<lm::LanguageModel> inner;
  switch (kind.empty() ? LanguageModelKind::Embedded : language_model_choices().parse(kind)) {
    case LanguageModelKind::Embedded: {
      lm::EmbeddedModelOptions o;
      o.data_dir = options.data_dir;
      inner = std::make_shared<lm::EmbeddedLanguageModel>(o);
      break;
    }
    case LanguageModelKind::OpenAi: inner = std::make_shared<lm::OpenAiCompletionsModel>(openai_options(options)); break;
  }
  return std::make_shared<lm::CachedLanguageModel>(inner);
}

std::shared_ptr<lm::LanguageModel> make_domain_language_model(const std::string& kind, const LanguageModelOptions& options,
                                                              const domains::Pack& pack, const pddl::Domain& domain,
                                                              const std::vector<const pddl::Problem*>& problems,
                                                              const std::vector<std::string>& goal_names) {
  if (!kind.empty() && kind != "embedded") return make_language_model(kind, options);
  lm::EmbeddedModelOptions o;
  o.data_dir = options.data_dir;
  if (!pack.spec().embedded_corpus.empty()) {
    o.corpus_files = pack.spec().embedded_corpus;
  } else {
    o.corpus_files.clear();
    o.function_words = true;
    std::set<std::pair<std::string, std::string>> seen;  // problems share most pairs
    for (const pddl::Problem* problem : problems) {
      lm::DomainDescription described =
          describe_for_language_model(domain, *problem, pack.language(), pack.language().qualifiers());
      described.goal_names = goal_names;
      const auto generated = lm::embedded_options_for_domain(described);
      o.noun_senses.insert(generated.noun_senses.begin(), generated.noun_senses.end());
      for (const auto& pair : generated.extra_corpus)
        if (seen.emplace(pair.command, pair.utterance).second) o.extra_corpus.push_back(pair);
    }
  }
  return std::make_shared<lm::CachedLanguageModel>(std::make_shared<lm::EmbeddedLanguageModel>(o));
}

lm::NounSenses dataset_noun_senses(const data::Dataset& dataset) {
  lm::NounSenses out;
  if (!dataset.pack().spec().embedded_corpus.empty()) return out;
  // As make_domain_language_model gathers them: over the problems.
  for (const std::string& id : dataset.problem_ids()) {
    const auto task = dataset.task(id);
    const lm::NounSenses senses = lm::domain_noun_senses(describe_for_language_model(
        *dataset.domain(), task->problem(), dataset.pack().language(), dataset.pack().language().qualifiers()));
    out.insert(senses.begin(), senses.end());
  }
  return out;
}

std::map<std::string, std::string> dataset_type_nouns(const data::Dataset& dataset) {
  std::map<std::string, std::string> out;
  if (!dataset.pack().spec().embedded_corpus.empty()) return out;
  for (const std::string& id : dataset.problem_ids()) {
    const auto task = dataset.task(id);
    for (const std::string& type : lm::domain_noun_types(describe_for_language_model(
             *dataset.domain(), task->problem(), dataset.pack().language(), dataset.pack().language().qualifiers())))
      if (!out.count(type)) out[type] = lm::WordNetLexicon::instance().type_noun(type);
  }
  return out;
}

// The embedded model trains (or loads from its cache) one model per prompt
// block of few-shot examples, on first use: score one example under each
// block the problems will use (the speaker model's, whose commands mark the
// numbered places of each problem as the utterance model does; the literal
// listener's; the empty prompt's) in one batch, so that they train side by
// side before the plans start.
void warm_up_language_model(lm::LanguageModel& lm, const data::Dataset& ds, const std::vector<std::string>& problem_ids) {
  std::vector<lm::ScoreRequest> batch;
  try {
    auto add = [&](const std::vector<commands::FewShotExample>& examples) {
      if (!examples.empty())
        batch.push_back({commands::build_prompt(examples, examples.front().command),
                         commands::utterance_continuation(examples.front().utterance)});
    };
    const std::vector<commands::FewShotExample> speaker = ds.pack().fewshot(/*literal=*/false);
    std::set<std::string> problems;
    std::set<std::vector<std::string>> numberings;
    for (const std::string& id : problem_ids) {
      if (!problems.insert(id).second) continue;
      const pddl::Problem problem = pddl::load_problem(*ds.domain(), ds.problem_path(id), false);
      const auto numbered = numbered_place_names(*ds.domain(), problem, ds.pack().language());
      if (!numberings.insert(numbered).second) continue;
      std::vector<commands::FewShotExample> marked = speaker;
      for (commands::FewShotExample& ex : marked) ex.command = util::mark_numbered(ex.command, numbered);
      add(marked);
    }
    if (ds.pack().spec().literal.enabled) add(literal_listener_setup(ds.pack_ptr()).examples);
    // The empty prompt (a joint plan with nothing to say) has a model of its own.
    batch.push_back({std::string(commands::kEmptyCommandPrompt), commands::utterance_continuation("ok")});
    lm.score(batch);
  } catch (const std::exception&) {
    // Only a warm-up: a pack without examples loads when it is first used.
  }
}

std::shared_ptr<lm::LanguageModel> make_dataset_language_model(const std::string& kind,
                                                               const LanguageModelOptions& options,
                                                               const data::Dataset& dataset) {
  if ((!kind.empty() && kind != "embedded") || !dataset.pack().spec().embedded_corpus.empty())
    return make_domain_language_model(kind, options, dataset.pack(), *dataset.domain(), {});
  // The problems of the recorded plans, in the plans' order, with their
  // candidate goals' labels (an error in one stops here, as the bench would
  // on its plans); a folder without plans: every problem, with the pack's
  // goals for it, but for those that do not ground (they have no session).
  std::vector<data::PlanRecord> problem_only;
  std::vector<const data::PlanRecord*> sources;
  for (const auto& p : dataset.plans()) sources.push_back(&p);
  const bool skip_bad = sources.empty();
  if (sources.empty()) {
    for (const std::string& id : dataset.problem_ids()) {
      data::PlanRecord only;
      only.id = only.problem_id = id;
      problem_only.push_back(std::move(only));
    }
    for (const auto& p : problem_only) sources.push_back(&p);
  }
  std::vector<std::shared_ptr<const pddl::Task>> tasks;
  std::vector<const pddl::Problem*> problems;
  std::set<std::string> ids;
  std::vector<std::string> goal_names;
  for (const data::PlanRecord* p : sources) {
    if (!ids.insert(p->problem_id).second) continue;
    std::shared_ptr<const pddl::Task> task;
    std::vector<data::GoalSpec> goals;
    try {
      task = dataset.task(p->problem_id);
      goals = dataset.candidate_goals(*p);
    } catch (const InputError&) {
      if (!skip_bad) throw;
      continue;
    }
    tasks.push_back(task);
    problems.push_back(&task->problem());
    for (const auto& g : goals)
      if (std::find(goal_names.begin(), goal_names.end(), g.label) == goal_names.end()) goal_names.push_back(g.label);
  }
  return make_domain_language_model(kind, options, dataset.pack(), *dataset.domain(), problems, goal_names);
}

// ---- listener setup ---------------------------------------------------------

std::string language_data_dir() { return util::data_dir() + "/language"; }

LiteralListenerSetup literal_listener_setup(domains::PackPtr pack, const std::string& data_dir) {
  if (!pack) throw InputError("the literal listener needs a domain pack");
  if (!pack->spec().literal.enabled || pack->language().salient_actions.empty())
    throw InputError("domain " + pack->name() + " has no literal listener (its pack declares no salient actions" +
                     std::string(pack->spec().literal.enabled ? "" : " or disables literal_listener") + ")");
  LiteralListenerSetup setup;
  setup.config = pack->language();
  setup.temperature = pack->spec().literal.temperature;
  setup.examples = pack->fewshot(/*literal=*/true, data_dir);
  setup.pack = std::move(pack);
  return setup;
}

LiteralListenerSetup literal_listener_setup(const std::string& domain, const std::string& data_dir) {
  return literal_listener_setup(domains::builtin_pack(domain), data_dir);
}

// ---- candidates and commands --------------------------------------------------

std::vector<commands::Term> literal_candidate_actions(const pddl::Task& task, const pddl::State& s,
                                                      const domains::Pack& pack) {
  return pack.literal_candidates(task, s);
}

std::vector<commands::Command> literal_commands(const pddl::Task& task, const pddl::State& s,
                                                const LiteralListenerSetup& setup) {
  const auto candidates = literal_candidate_actions(task, s, *setup.pack);
  // Qualifiers (colours, item types) are static facts of the problem, so they
  // are looked up in the task rather than the state.
  const commands::QualifierLookup qualifier_of = setup.pack->qualifier_of(task);
  commands::LanguageConfig config = setup.config;
  config.numbered_names = numbered_place_names(task.domain(), task.problem(), config);
  return commands::enumerate_literal_candidates(candidates, config, qualifier_of, type_lookup(task, *setup.pack));
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
  // The examples name numbered places as the commands do ("shelf#3").
  std::vector<std::string> numbered;
  for (const auto& c : commands)
    for (const auto& n : c.numbered)
      if (std::find(numbered.begin(), numbered.end(), n) == numbered.end()) numbered.push_back(n);
  std::vector<commands::FewShotExample> examples = setup.examples;
  for (commands::FewShotExample& ex : examples) ex.command = util::mark_numbered(ex.command, numbered);
  std::vector<lm::ScoreRequest> batch;
  batch.reserve(commands.size());
  for (const auto& c : commands) batch.push_back({commands::build_prompt(examples, c.llm_form()), continuation});
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
  return rank_commands(literal_commands(task, s, setup), utterance, setup, lm);
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
