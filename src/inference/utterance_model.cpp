#include "inference/utterance_model.hpp"

#include "util/data_dir.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "commands/enumerate.hpp"
#include "lm/wordnet_lexicon.hpp"
#include "language/lm_domain.hpp"
#include "commands/salient.hpp"
#include "util/error.hpp"
#include "util/numbered_names.hpp"

namespace clips::inference {

namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

double log_sum_exp(const std::vector<double>& x) {
  double m = kNegInf;
  for (double v : x) m = std::max(m, v);
  if (m == kNegInf) return kNegInf;
  double z = 0;
  for (double v : x) z += std::exp(v - m);
  return m + std::log(z);
}

// log(exp(a) - exp(b)) for a >= b; -inf when they are (nearly) equal.
double log_minus(double a, double b) {
  if (!(a > b)) return kNegInf;
  return a + std::log1p(-std::exp(b - a));
}

}  // namespace

std::vector<CommandScore> merge_requests(const HypothesisUtterance& own, const HypothesisUtterance& alone,
                                         double share) {
  std::vector<CommandScore> out;
  std::vector<double> terms;  // per entry of out, its log weight
  std::vector<double> rest;   // the readings that ask for no command
  auto add = [&](const HypothesisUtterance& r, double log_share) {
    std::vector<double> mine;
    for (const CommandScore& c : r.commands) {
      if (!(c.prior > 0)) continue;
      const double t = log_share + std::log(c.prior) + c.log_lm;
      mine.push_back(t - log_share);
      auto it = std::find_if(out.begin(), out.end(), [&](const CommandScore& o) { return o.command == c.command; });
      if (it == out.end()) {
        out.push_back(c);
        terms.push_back(t);
      } else {
        double& w = terms[static_cast<size_t>(it - out.begin())];
        w = log_sum_exp({w, t});
      }
    }
    // What the commands leave of the likelihood: the empty prompt's part.
    rest.push_back(log_share + log_minus(r.log_likelihood, log_sum_exp(mine)));
  };
  add(own, std::log1p(-share));
  add(alone, std::log(share));
  std::vector<double> all = terms;
  all.insert(all.end(), rest.begin(), rest.end());
  const double z = log_sum_exp(all);
  for (size_t i = 0; i < out.size(); ++i) {
    out[i].posterior = z == kNegInf ? 0.0 : std::exp(terms[i] - z);
  }
  return out;
}

util::Choices<SpeakerRule>& speaker_rule_choices() {
  static util::Choices<SpeakerRule> table(
      "speaker rule",
      {{SpeakerRule::Paper, "paper", "joint commands keep the speaker's own actions (the paper's)", {}},
       {SpeakerRule::Code, "code", "the reference code drops them all", {}}});
  return table;
}
SpeakerRule parse_speaker_rule(const std::string& text) { return speaker_rule_choices().parse(text); }
std::string to_string(SpeakerRule r) { return speaker_rule_choices().name(r); }

util::Choices<UtteranceTiming>& utterance_timing_choices() {
  static util::Choices<UtteranceTiming> table(
      "utterance timing",
      {{UtteranceTiming::Before, "before", "s_{k-1}, the reference code's alignment", {}},
       {UtteranceTiming::After, "after", "s_k, where it was said, as in the paper", {}}});
  return table;
}
UtteranceTiming parse_utterance_timing(const std::string& text) { return utterance_timing_choices().parse(text); }
std::string to_string(UtteranceTiming t) { return utterance_timing_choices().name(t); }

UtteranceModel::UtteranceModel(std::shared_ptr<const pddl::Task> task, domains::PackPtr pack,
                               const UtteranceModelOptions& options)
    : task_(std::move(task)),
      config_(pack->language()),
      rollout_kind_(pack->spec().inference.rollout.kind),
      plans_(options.plans.value_or(pack->spec().inference.rollout.plans)),
      options_(options) {
  // Tie-breaking rollouts branch a greedy rollout; a searched rollout (VH) has one plan.
  if (rollout_kind_ != RolloutKind::Greedy) plans_ = domains::RolloutSettings::Plans::Single;
  if (options_.speaker_rule == SpeakerRule::Paper) {
    config_.speaker_actions = config_.paper_speaker_actions;
    config_.exclude_chains = config_.paper_exclude_chains;
  }
  examples_ = pack->fewshot(/*literal=*/false, options_.language_dir);
  const pddl::Task& t = *task_;
  const auto& dom = t.domain();
  // Places said by their number: commands and the examples' commands mark it.
  config_.numbered_names = language::numbered_place_names(dom, t.problem(), config_);
  for (commands::FewShotExample& ex : examples_) ex.command = util::mark_numbered(ex.command, config_.numbered_names);
  for (int o = 0; o < t.num_objects(); ++o)
    type_of_[t.object_name(o)] = dom.types[t.problem().objects[o].type].name;
  // Qualifier candidates: every (object, value) pair whose atom is dynamic or
  // statically true; the state decides among dynamic ones.
  std::vector<std::string> described = config_.qualifiers();
  described.insert(described.end(), config_.location_predicates.begin(), config_.location_predicates.end());
  for (const std::string& name : described) {
    QualifierAtoms q{name, {}};
    if (auto pred = dom.find_predicate(name); pred && dom.predicates[*pred].arg_types.size() == 2) {
      const int obj_pos = config_.is_location(name) ? 0 : config_.qualifier_object_arg - 1;
      for (int o = 0; o < t.num_objects(); ++o)
        for (int v = 0; v < t.num_objects(); ++v) {
          std::vector<pddl::ObjectId> args(2);
          args[obj_pos] = o;
          args[1 - obj_pos] = v;
          bool typed = true;
          for (int i = 0; i < 2; ++i)
            typed = typed && dom.is_subtype(t.problem().objects[args[i]].type, dom.predicates[*pred].arg_types[i]);
          if (!typed) continue;
          // A place named by a code ("c3-4") is nothing a speaker says.
          if (config_.is_location(name) && !lm::WordNetLexicon::instance().sayable_name(t.object_name(v))) continue;
          auto ref = t.atom(*pred, args);
          if (ref.bit >= 0 || ref.value) q.of_object[t.object_name(o)].push_back({t.object_name(v), ref});
        }
    }
    qualifiers_.push_back(std::move(q));
  }
  if (const std::string& flag = pack->spec().inference.rollout.speaker_flag;
      rollout_kind_ == RolloutKind::WeightedAStar && !flag.empty()) {
    auto pred = dom.find_predicate(flag);
    auto speaker = t.find_object(config_.speaker);
    if (!pred || !speaker) throw InputError("the " + pack->name() + " rollout needs (" + flag + " " + config_.speaker + ")");
    speaker_flag_ = t.atom(*pred, {*speaker});
  }
}

std::vector<commands::Term> UtteranceModel::qualifiers(const std::string& object, const pddl::State& s) const {
  std::vector<commands::Term> out;
  for (const auto& q : qualifiers_) {
    auto it = q.of_object.find(object);
    if (it == q.of_object.end()) continue;
    for (const auto& [value, ref] : it->second)
      if (task_->test(s, ref)) {
        commands::Term t{q.predicate, {}};
        t.args = config_.qualifier_object_arg == 1 || config_.is_location(q.predicate)
                     ? std::vector<std::string>{object, value}
                                                   : std::vector<std::string>{value, object};
        out.push_back(std::move(t));
        break;
      }
  }
  return out;
}

commands::Term UtteranceModel::term(pddl::ActionId a) const {
  const auto& ga = task_->action(a);
  commands::Term t{task_->domain().actions[ga.schema].name, {}};
  for (auto o : ga.args) t.args.push_back(task_->object_name(o));
  return t;
}

std::vector<pddl::ActionId> UtteranceModel::rollout(const search::Policy& policy, const pddl::State& s) const {
  if (rollout_kind_ == RolloutKind::Greedy) return policy.rollout(s, options_.rollout_steps);
  // VH: the principal may not collect new items, so every remaining item is the
  // helper's to grab and can be delegated in a command.
  pddl::State start = s;
  if (speaker_flag_) task_->set(start, *speaker_flag_, true);
  if (policy.spec().is_goal(start)) return {};
  search::SearchOptions so;
  so.max_nodes = options_.astar_max_nodes;
  so.h_weight = options_.astar_weight;
  so.prune = false;  // the rollout uses all legal actions
  auto r = search::plan(policy.spec(), policy.heuristic(), start, so);
  if (r.status == search::SearchStatus::Failure || r.terminal < 0) return {};
  if (r.status == search::SearchStatus::Success && !r.plan.empty()) return r.plan;
  // Budget exhausted: the path to the best frontier node (a partial plan).
  std::vector<pddl::ActionId> path;
  for (int id = r.terminal; r.nodes[id].parent >= 0; id = r.nodes[id].parent) path.push_back(r.nodes[id].action);
  return {path.rbegin(), path.rend()};
}

std::vector<commands::Command> UtteranceModel::plan_commands(const std::vector<pddl::ActionId>& plan,
                                                            const pddl::State& s) const {
  std::vector<commands::Term> terms;
  for (pddl::ActionId a : plan) terms.push_back(term(a));
  // Qualifiers are read in the scoring state (objects keep their colour / type).
  auto salient = commands::extract_salient(
      terms, config_, [&](const std::string& o) { return qualifiers(o, s); });
  // Where an action leaves its object is part of what the speaker may say.
  if (config_.destinations)
    for (commands::SalientAction& a : salient)
      if (const commands::SalientActionRule* r = config_.salient_rule(a.action.name);
          r && r->destination_arg > 0 && static_cast<size_t>(r->destination_arg) <= a.action.args.size() &&
          lm::WordNetLexicon::instance().sayable_name(a.action.args[static_cast<size_t>(r->destination_arg - 1)]))
        a.predicates.push_back({commands::kDestinationPredicate,
                                {a.focal, a.action.args[static_cast<size_t>(r->destination_arg - 1)]}});
  return commands::enumerate_commands(salient, config_, [this](const std::string& o) {
    auto it = type_of_.find(o);
    return it == type_of_.end() ? std::string("object") : it->second;
  });
}

std::vector<commands::Command> UtteranceModel::commands_at(const search::Policy& policy, const pddl::State& s) const {
  return plan_commands(rollout(policy, s), s);
}

SpeakerPlans UtteranceModel::single_plan(const search::Policy& policy, const pddl::State& s) const {
  return {SpeakerPlan{1.0, rollout(policy, s)}};
}

SpeakerPlans UtteranceModel::speaker_plans(search::Policy& policy, const pddl::State& s,
                                           const search::SearchOptions& refine) const {
  if (plans_ == domains::RolloutSettings::Plans::Single) return single_plan(policy, s);
  search::TiedRolloutOptions o = options_.tied;
  o.max_steps = options_.rollout_steps;
  SpeakerPlans out;
  for (auto& r : search::tied_rollouts(policy, s, o, refine)) out.push_back({r.weight, std::move(r.actions)});
  return out;
}

std::vector<UtteranceModel::WeightedCommand> UtteranceModel::weighted_commands(const SpeakerPlans& plans,
                                                                               const pddl::State& s,
                                                                               double& no_command) const {
  std::vector<WeightedCommand> out;
  no_command = 0;
  for (const SpeakerPlan& p : plans) {
    const std::vector<commands::Command> cs = plan_commands(p.actions, s);
    if (cs.empty()) {
      no_command += p.weight;
      continue;
    }
    const double share = p.weight / static_cast<double>(cs.size());
    for (const commands::Command& c : cs) {
      auto it = std::find_if(out.begin(), out.end(), [&](const WeightedCommand& w) { return w.command == c; });
      if (it == out.end()) out.push_back({c, share});
      else it->weight += share;
    }
  }
  return out;
}

std::vector<std::vector<HypothesisUtterance>> UtteranceModel::score(
    const std::vector<const search::Policy*>& policies, const pddl::State& s,
    const std::vector<std::string>& utterances, lm::LanguageModel& lm) const {
  std::vector<SpeakerPlans> plans;
  for (const search::Policy* p : policies) plans.push_back(single_plan(*p, s));
  return score(plans, s, utterances, lm);
}

std::vector<std::vector<HypothesisUtterance>> UtteranceModel::score(const std::vector<SpeakerPlans>& plans,
                                                                    const pddl::State& s,
                                                                    const std::vector<std::string>& utterances,
                                                                    lm::LanguageModel& lm) const {
  return score(plans, {}, s, utterances, lm);
}

namespace {

// The words of a name: split on '-', '_' and spaces, lower case, no digits.
std::vector<std::string> name_words(const std::string& name) {
  std::vector<std::string> out;
  std::string w;
  auto flush = [&] {
    if (!w.empty()) out.push_back(w);
    w.clear();
  };
  for (char c : name) {
    if (c == '-' || c == '_' || std::isspace(static_cast<unsigned char>(c))) flush();
    else if (std::isalpha(static_cast<unsigned char>(c))) w.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  flush();
  return out;
}

}  // namespace

commands::Command UtteranceModel::goal_statement(const std::string& label, const std::string& condition,
                                                 const pddl::State& s) const {
  commands::Command c;
  c.printed_form = commands::PrintedForm::WhereClause;
  c.actions.push_back({"make", {config_.speaker_pronoun, "?goal1"}});
  c.variables.push_back({"goal1", "goal"});
  std::vector<std::string> words;
  auto add = [&](const std::string& w) {
    // Type nouns stay nouns (the corpus does not name goals with them either).
    if ((w.size() > 1 || std::isdigit(static_cast<unsigned char>(w[0]))) && !task_->domain().find_type(w) &&
        std::find(words.begin(), words.end(), w) == words.end())
      words.push_back(w);
  };
  // A numbered place's number is a word of its own ("shelf3": shelf, 3).
  auto add_name = [&](const std::string& name) {
    for (const auto& w : name_words(name)) add(w);
    if (std::find(config_.numbered_names.begin(), config_.numbered_names.end(), name) != config_.numbered_names.end()) {
      const std::string marked = util::number_marked(name);
      add(marked.substr(marked.find('#') + 1));
    }
  };
  {
    std::string part;
    for (char ch : label + "-") {
      if (ch == '-' || ch == '_' || std::isspace(static_cast<unsigned char>(ch))) {
        if (!part.empty()) add_name(part);
        part.clear();
      } else {
        part.push_back(ch);
      }
    }
  }
  // The objects the condition names (not the agents), and their qualifiers.
  std::string token;
  auto object = [&](const std::string& name) {
    if (name.empty() || name == config_.speaker || name == config_.listener || !task_->find_object(name)) return;
    add_name(name);
    for (const auto& q : qualifiers(name, s))
      for (const auto& a : q.args)
        if (a != name)
          for (const auto& w : name_words(a)) add(w);
  };
  for (char ch : condition + " ") {
    if (ch == '(' || ch == ')' || std::isspace(static_cast<unsigned char>(ch))) {
      object(token);
      token.clear();
    } else {
      token.push_back(ch);
    }
  }
  for (const auto& w : words) c.predicates.push_back({"named", {"?goal1", w}});
  return c;
}

std::vector<std::vector<HypothesisUtterance>> UtteranceModel::score(const std::vector<SpeakerPlans>& plans,
                                                                    const std::vector<commands::Command>& goals,
                                                                    const pddl::State& s,
                                                                    const std::vector<std::string>& utterances,
                                                                    lm::LanguageModel& lm) const {
  std::vector<std::vector<HypothesisUtterance>> out(utterances.size(),
                                                    std::vector<HypothesisUtterance>(plans.size()));
  if (utterances.empty() || plans.empty()) return out;
  // Commands and prompts depend on the hypothesis only; the batch is
  // utterance-major over (hypothesis, prompt). A hypothesis' prompts are its
  // distinct commands, then the empty prompt if some plan has no command.
  std::vector<std::vector<WeightedCommand>> cmds(plans.size());
  std::vector<std::vector<commands::WeightedPrompt>> prompts(plans.size());
  size_t per_utterance = 0;
  for (size_t h = 0; h < plans.size(); ++h) {
    double no_command = 0;
    cmds[h] = weighted_commands(plans[h], s, no_command);
    const double gamma = h < goals.size() && !goals[h].predicates.empty() ? config_.goal_statements : 0.0;
    // A share of the speakers who state the goal also say what they want done.
    const double both = gamma > 0 && !cmds[h].empty() ? gamma * config_.goal_with_command : 0.0;
    // (Of a plan with no command, the goal statement is all it says.)
    const double alone = gamma - both + no_command * both;
    // Plans with no command speak under the empty prompt (all of them: 1).
    const double empty_weight = (cmds[h].empty() ? 1.0 : no_command) * (1 - gamma);
    if (both > 0) {
      std::vector<WeightedCommand> joined;
      joined.reserve(cmds[h].size());
      for (const WeightedCommand& c : cmds[h]) {
        commands::Command g = goals[h];
        g.actions.insert(g.actions.end(), c.command.actions.begin(), c.command.actions.end());
        g.predicates.insert(g.predicates.end(), c.command.predicates.begin(), c.command.predicates.end());
        g.variables.insert(g.variables.end(), c.command.variables.begin(), c.command.variables.end());
        g.binding = c.command.binding;
        joined.push_back({std::move(g), c.weight * both});
      }
      for (WeightedCommand& c : cmds[h]) c.weight *= 1 - gamma;
      for (WeightedCommand& j : joined) cmds[h].push_back(std::move(j));
    } else {
      for (WeightedCommand& c : cmds[h]) c.weight *= 1 - gamma;
    }
    if (alone > 0) cmds[h].push_back({goals[h], alone});
    for (const WeightedCommand& c : cmds[h])
      prompts[h].push_back({commands::build_prompt(examples_, c.command.llm_form()), c.weight});
    if (empty_weight > 0) prompts[h].push_back({std::string(commands::kEmptyCommandPrompt), empty_weight});
    per_utterance += prompts[h].size();
  }
  std::vector<lm::ScoreRequest> batch;
  batch.reserve(per_utterance * utterances.size());
  for (const auto& u : utterances) {
    const std::string cont = commands::utterance_continuation(u);
    for (size_t h = 0; h < plans.size(); ++h)
      for (const auto& p : prompts[h]) batch.push_back({p.prompt, cont});
  }
  const std::vector<double> scores = lm.score(batch);
  if (scores.size() != batch.size()) throw lm::LmError(lm.name() + ": wrong number of scores");
  auto ground = [&](const commands::Command& c, bool listener) {
    std::vector<std::string> acts;
    for (const commands::Term& t : commands::substitute(c.actions, c.binding)) {
      const commands::Term named = commands::to_agent_names(t, config_);
      const commands::SalientActionRule* rule = config_.salient_rule(named.name);
      const bool by_listener = rule && rule->agent_arg >= 1 && rule->agent_arg <= static_cast<int>(named.args.size()) &&
                               named.args[static_cast<size_t>(rule->agent_arg - 1)] == config_.listener;
      if (by_listener == listener) acts.push_back(commands::to_pddl(named));
    }
    return acts;
  };
  size_t k = 0;
  for (size_t ui = 0; ui < utterances.size(); ++ui)
    for (size_t h = 0; h < plans.size(); ++h) {
      HypothesisUtterance& r = out[ui][h];
      std::vector<double> terms, lms;
      for (const auto& p : prompts[h]) {
        lms.push_back(scores[k++]);
        terms.push_back(std::log(p.weight) + lms.back());
      }
      r.log_likelihood = log_sum_exp(terms);
      for (size_t c = 0; c < cmds[h].size(); ++c) {
        const double post = r.log_likelihood == kNegInf ? 0.0 : std::exp(terms[c] - r.log_likelihood);
        r.commands.push_back({cmds[h][c].command.display_form(), lms[c], post, cmds[h][c].weight,
                              ground(cmds[h][c].command, true), ground(cmds[h][c].command, false)});
      }
    }
  return out;
}

}  // namespace clips::inference
