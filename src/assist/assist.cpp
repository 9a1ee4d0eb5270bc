#include "assist/assist.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "heuristics/basic.hpp"
#include "model/spec.hpp"
#include "search/astar.hpp"
#include "search/tied_rollouts.hpp"
#include "util/error.hpp"

namespace clips::assist {

using model::kInf;
using pddl::ActionId;

util::Choices<QaFloor>& qa_floor_choices() {
  static util::Choices<QaFloor> table(
      "Q_MDP floor", {{QaFloor::DeadEnds, "dead-ends", "only unreachable goals, the floor's stated purpose", {}},
                      {QaFloor::Horizon, "horizon", "every value, the reference formula", {}}});
  return table;
}
std::string to_string(QaFloor f) { return qa_floor_choices().name(f); }
QaFloor parse_qa_floor(const std::string& text) { return qa_floor_choices().parse(text); }

util::Choices<AssistRule>& assist_rule_choices() {
  static util::Choices<AssistRule> table(
      "assistance rule",
      {{AssistRule::Paper, "paper", "the paper's rule, for the paper's tables", {}},
       {AssistRule::Request, "request", "the one that carries out what the instruction most probably asked for", {}}});
  return table;
}
std::string to_string(AssistRule r) { return assist_rule_choices().name(r); }
AssistRule parse_assist_rule(const std::string& text) { return assist_rule_choices().parse(text); }

std::vector<std::pair<int, int>> salient_argument_table(const pddl::Task& task, const commands::LanguageConfig& config) {
  const auto& actions = task.domain().actions;
  std::vector<std::pair<int, int>> out(actions.size(), {-1, -1});
  for (size_t i = 0; i < actions.size(); ++i)
    if (const auto* r = config.salient_rule(actions[i].name)) {
      const int n = static_cast<int>(actions[i].param_types.size());
      if (r->agent_arg >= 1 && r->agent_arg <= n && r->focal_arg >= 1 && r->focal_arg <= n)
        out[i] = {r->agent_arg - 1, r->focal_arg - 1};
    }
  return out;
}

using pddl::State;

namespace {
bool debug_qmdp() {
  static const bool on = std::getenv("CLIPS_DEBUG_QMDP") != nullptr;
  return on;
}
}  // namespace

double plan_cost(const model::Specification& spec, const std::vector<ActionId>& plan) {
  double c = 0;
  for (ActionId a : plan) c += spec.cost(a);
  return c;
}

double human_cost(const model::Specification& spec, const std::vector<ActionId>& plan, const std::string& principal) {
  double c = 0;
  const pddl::Task& t = spec.task();
  for (ActionId a : plan) {
    const auto& ga = t.action(a);
    if (!ga.args.empty() && t.object_name(ga.args[0]) == principal) c += spec.cost(a);
  }
  return c;
}

namespace {

const double kLog10 = std::log(10.0);

// The weight below which a hypothesis is ignored. The paper's cut-off (0.02)
// skips hypotheses too unlikely to matter among the paper's 8; with many
// candidates a flat posterior puts all of them below it, and the assistant
// would decide on none (Q_MDP's first applicable action). So the cut-off is
// at most half the largest weight: the same as the paper's whenever some
// hypothesis weighs 0.04 or more, as one always does with up to 25
// hypotheses (the paper's 8, the example domains' goal sets).
}  // namespace

void refine_live(AssistSetup& setup, const std::vector<Hypothesis>& belief, const pddl::State& s,
                 const std::function<void()>& between) {
  if (!setup.refine) return;
  const double cut = live_threshold(belief, setup.weight_threshold);
  for (const Hypothesis& h : belief) {
    if (h.weight < cut) continue;
    if (between) between();
    h.policy->refine(s, setup.refine_options);
  }
  setup.refine = false;
}

double live_threshold(const std::vector<Hypothesis>& belief, double threshold) {
  double top = 0;
  for (const Hypothesis& h : belief) top = std::max(top, h.weight);
  return std::min(threshold, top / 2);
}

namespace {

// How much of the request the assistant's part of `plan` carries out, and
// how much of what the principal said they would do it takes over. Actions
// match on their name, agent and focal object (not on the place or tool, which
// the speaker rarely fixes).
struct RequestMatcher {
  const AssistSetup& setup;
  const pddl::Task& task;
  pddl::ObjectId assistant = -1;

  explicit RequestMatcher(const AssistSetup& s) : setup(s), task(*s.task) {
    if (auto o = task.find_object(s.assistant)) assistant = *o;
  }
  // (schema, focal object) of a salient action by `agent`; schema -1 if not salient.
  std::pair<int, pddl::ObjectId> key(pddl::ActionId a, pddl::ObjectId* agent = nullptr) const {
    const auto& ga = task.action(a);
    if (static_cast<size_t>(ga.schema) >= setup.salient_args.size()) return {-1, -1};
    const auto [ag, focal] = setup.salient_args[static_cast<size_t>(ga.schema)];
    if (ag < 0) return {-1, -1};
    if (agent) *agent = ga.args[static_cast<size_t>(ag)];
    return {ga.schema, ga.args[static_cast<size_t>(focal)]};
  }
  // Score of one hypothesis' request against a plan: Σ_c P(c) (share of c's
  // assistant part the plan's assistant does - share of c's principal part
  // it does instead of the principal - kExtraObject per object the
  // assistant handles that c does not mention). So among equally good
  // plans the assistant does what it was asked, leaves alone what the
  // principal said they would do, and takes on no more than it was asked to.
  static constexpr double kExtraObject = 0.5;
  double score(const Request& request, const std::vector<ActionId>& plan) const {
    std::vector<std::pair<int, pddl::ObjectId>> done;
    std::vector<pddl::ObjectId> handled;
    for (ActionId a : plan) {
      pddl::ObjectId agent = -1;
      auto k = key(a, &agent);
      if (k.first < 0 || agent != assistant) continue;
      done.push_back(k);
      if (std::find(handled.begin(), handled.end(), k.second) == handled.end()) handled.push_back(k.second);
    }
    auto share = [&](const std::vector<ActionId>& part) {
      if (part.empty()) return 0.0;
      double n = 0;
      for (ActionId a : part)
        if (std::find(done.begin(), done.end(), key(a)) != done.end()) n += 1;
      return n / static_cast<double>(part.size());
    };
    double v = 0;
    for (const RequestedCommand& c : request) {
      double extra = 0;
      for (pddl::ObjectId o : handled) {
        bool mentioned = false;
        for (ActionId a : c.assistant_part) mentioned = mentioned || key(a).second == o;
        if (!mentioned) extra += 1;
      }
      v += c.probability * (share(c.assistant_part) - share(c.principal_part) - kExtraObject * extra);
    }
    return v;
  }
};

// The net effect of an assistant part (adds true, deletes false; the turn
// predicate left out), as sorted (atom, value) pairs: a request's meaning,
// whatever place its ground actions were said at.
std::vector<std::pair<int, bool>> net_effect(const AssistSetup& setup, const std::vector<ActionId>& part) {
  const pddl::Task& task = *setup.task;
  const auto turn = task.domain().find_predicate(setup.turn_predicate);
  std::vector<std::pair<int, bool>> net;
  auto set = [&](int bit, bool v) {
    if (turn && task.atom_info(bit).first == *turn) return;
    for (auto& [b, val] : net)
      if (b == bit) {
        val = v;
        return;
      }
    net.emplace_back(bit, v);
  };
  for (ActionId a : part) {
    const auto& ga = task.action(a);
    for (int b : ga.eff.del) set(b, false);
    for (int b : ga.eff.add) set(b, true);
  }
  std::sort(net.begin(), net.end());
  return net;
}

// AssistRule::Request's commitment: what the live hypotheses most probably
// asked the assistant to do next, when at least kAskingShare of their weight
// reads the words as asking the assistant for something and kCommitShare of
// that asks for it next (by the net effect of the step asked next), it is not
// yet done in s, and doing it leaves
// the goals of most of their weight no costlier (their heuristic estimate
// after it at most the cheapest action's cost above the estimate now):
// the first step of the assistant's own plan for it, the principal frozen.
struct Commitment {
  ActionId action = -1;
  std::string command;
  double share = 0;
  bool leaves_principal_a_step = false;  // the principal's one more action was allowed
};
constexpr double kCommitShare = 0.5;
constexpr double kAskingShare = 0.5;
// How much dearer the principal's own actions are when the request rule asks
// whether a request makes a likely goal costlier (committed_request).
constexpr double kSparingFactor = 10;

std::optional<Commitment> committed_request(const AssistSetup& setup, const std::vector<const Hypothesis*>& live,
                                            const State& s, const std::vector<State>* since_instruction) {
  const pddl::Task& task = *setup.task;
  using Effect = std::vector<std::pair<int, bool>>;
  auto holds_in = [](const Effect& e, const State& x) {
    return std::all_of(e.begin(), e.end(), [&](const auto& bv) { return pddl::get_bit(x.data(), bv.first) == bv.second; });
  };
  // Each reading is grouped by the step it asks for next: the effect of the
  // shortest prefix of its assistant part that does not hold yet (after the
  // longest one that does), so things asked together ("open the cupboard,
  // then fetch the flour") are done in the order asked. Readings that differ
  // only in what follows ("fetch it" and "fetch it and hand it to me") agree
  // on that step, so a request
  // read several ways is still done. A reading whose whole part held at some
  // point since it was said is done: help given is not taken back to be given
  // again (an empty next step).
  struct Asked {
    Effect next;
    double weight = 0;
    std::map<std::string, double> texts;
  };
  std::vector<Asked> asked;
  double total = 0, asking = 0;
  for (const Hypothesis* h : live) {
    total += h->weight;
    if (!h->request) continue;
    for (const RequestedCommand& c : *h->request) {
      if (c.assistant_part.empty() || !(c.probability > 0)) continue;
      const std::vector<ActionId>& part = c.assistant_part;
      const Effect whole = net_effect(setup, part);
      if (whole.empty()) continue;
      const bool done = holds_in(whole, s) ||
                        (since_instruction && std::any_of(since_instruction->begin(), since_instruction->end(),
                                                          [&](const State& x) { return holds_in(whole, x); }));
      Effect next;
      if (!done) {
        auto prefix = [&](size_t k) {
          return net_effect(setup, {part.begin(), part.begin() + static_cast<std::ptrdiff_t>(k)});
        };
        size_t from = 0;
        for (size_t k = part.size(); k-- > 1;)
          if (holds_in(prefix(k), s)) {
            from = k;
            break;
          }
        for (size_t k = from + 1; k <= part.size() && next.empty(); ++k)
          if (auto e = prefix(k); !e.empty() && !holds_in(e, s)) next = std::move(e);
        if (next.empty()) next = whole;
      }
      auto it = std::find_if(asked.begin(), asked.end(), [&](const Asked& a) { return a.next == next; });
      if (it == asked.end()) {
        asked.push_back({std::move(next), 0, {}});
        it = asked.end() - 1;
      }
      it->weight += h->weight * c.probability;
      it->texts[c.text] += h->weight * c.probability;
      asking += h->weight * c.probability;
    }
  }
  // Shares are of the readings that ask the assistant for something: a goal
  // statement read beside a request ("I want the red can, could you get
  // it?") neither asks nor refuses. Yet the words must mostly ask.
  if (asked.empty() || !(total > 0) || asking < kAskingShare * total) return std::nullopt;
  const Asked& top = *std::max_element(asked.begin(), asked.end(),
                                       [](const Asked& a, const Asked& b) { return a.weight < b.weight; });
  if (top.next.empty() || top.weight < kCommitShare * asking) return std::nullopt;
  const Effect& next = top.next;
  // The goal: what the request makes true (what it deletes, for a request
  // that only deletes, as an unlock does).
  std::string goal;
  for (const auto& [bit, v] : next)
    if (v) goal += " " + task.atom_str(bit);
  if (goal.empty())
    for (const auto& [bit, v] : next) goal += " (not " + task.atom_str(bit) + ")";
  const Hypothesis* heaviest = *std::max_element(live.begin(), live.end(),
                                                 [](const Hypothesis* a, const Hypothesis* b) { return a->weight < b->weight; });
  std::shared_ptr<model::Specification> spec;
  try {
    spec = std::make_shared<model::Specification>(setup.task, "(and" + goal + ")", heaviest->policy->spec().profile());
  } catch (const InputError&) {
    return std::nullopt;
  }
  State start = s;
  const bool can_freeze = model::can_freeze(task, setup.principal);
  if (can_freeze) start = model::freeze(task, s, setup.principal);
  heuristics::FFHeuristic ff;
  ff.prepare(*spec, start);
  search::SearchOptions o = setup.refine_options;
  o.max_nodes = std::min<size_t>(o.max_nodes, size_t{1} << 16);
  search::SearchResult r = search::astar(*spec, ff, start, o);
  State end = start;
  if (r.status == search::SearchStatus::Success) {
    // Where the request leaves the world, the principal free again.
    for (ActionId a : r.plan) end = task.apply(end, a);
    if (can_freeze) end = model::unfreeze(task, end, setup.principal);
  } else if (can_freeze) {
    // What was asked may need the principal's part first ("carry it up,
    // I'll unlock the door"): the joint plan in which the principal does
    // only what the assistant cannot, its own actions kSparingFactor times
    // dearer.
    auto joint = std::make_shared<model::Specification>(
        setup.task, "(and" + goal + ")",
        model::scaled_assistant(heaviest->policy->spec().profile(), heaviest->policy->spec().profile().name + "-sparing",
                                setup.principal, setup.noop_action, kSparingFactor));
    heuristics::FFHeuristic joint_ff;
    joint_ff.prepare(*joint, s);
    r = search::astar(*joint, joint_ff, s, o);
    if (r.status == search::SearchStatus::Success) {
      end = s;
      for (ActionId a : r.plan) end = task.apply(end, a);
    }
  }
  if (r.status != search::SearchStatus::Success || r.plan.empty() || !task.applicable(r.plan.front(), s.data()))
    return std::nullopt;
  // A plan that starts by waiting for the principal is no step towards it
  // (what was asked waits on the principal, or was handed back).
  if (setup.find_noop(task, setup.assistant) == r.plan.front()) return std::nullopt;
  double cheapest = kInf;
  for (ActionId a : task.applicable_actions(s)) cheapest = std::min(cheapest, heaviest->policy->spec().cost(a));
  const double tolerance = std::isfinite(cheapest) ? std::max(cheapest, 1.0) : 1.0;
  // Costlier is judged by the principal's effort: the principal who asked
  // has handed that part of the joint plan over, so a fetch the principal
  // could have made more cheaply is still theirs to ask for. Each likely
  // goal is valued with the principal's own actions kSparingFactor times
  // dearer (the sparing plans of the speaker model); a request that moves
  // the world away from the goal still costs the assistant the way back.
  // A step that gives the principal something ("bring me the jar") leaves
  // them its use, which they chose by asking: one more action of theirs is
  // not costlier (else the assistant would put away what it was asked to
  // hand over).
  double allowance = tolerance;
  if (const auto principal = task.find_object(setup.principal))
    for (const auto& [bit, v] : next) {
      const auto& args = task.atom_info(bit).second;
      if (v && std::find(args.begin(), args.end(), *principal) != args.end()) allowance = tolerance * (1 + kSparingFactor);
    }
  double costlier = 0;
  bool allowed_more = false;
  for (const Hypothesis* h : live) {
    const model::Specification& base = h->policy->spec();
    model::Specification sparing(setup.task, base.goal_text(),
                                 model::scaled_assistant(base.profile(), base.profile().name + "-sparing",
                                                         setup.principal, setup.noop_action, kSparingFactor));
    heuristics::FFHeuristic est;
    est.prepare(sparing, s);
    const double before = est.estimate(s.data()), after = est.estimate(end.data());
    if (!(after <= before + allowance)) costlier += h->weight;
    else if (after > before + tolerance) allowed_more = true;
  }
  if (costlier > 0.5 * total) return std::nullopt;
  Commitment c;
  c.action = r.plan.front();
  c.share = top.weight / asking;
  c.leaves_principal_a_step = allowed_more;
  double best = -1;
  for (const auto& [text, w] : top.texts)
    if (w > best) {
      best = w;
      c.command = text;
    }
  return c;
}

std::string with_value(const char* what, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, " %.3f", v);
  return what + std::string(buf);
}

// The rule that decided a Q_MDP choice, with its numbers. `best`: the
// candidate of highest expected value (waiting left out after a round of
// waits: `waited` is then the assistant's no-op, else -1).
std::string qmdp_reason(const Decision& d, const std::vector<ActionId>& acts, size_t best,
                        ActionId waited) {
  auto value_of = [&](ActionId a) {
    for (size_t i = 0; i < acts.size() && i < d.values.size(); ++i)
      if (acts[i] == a) return d.values[i];
    return std::numeric_limits<double>::quiet_NaN();
  };
  if (d.followed_request) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f%%", 100 * d.request_share);
    return "doing what was asked: \"" + d.request_command + "\" (" + buf +
           " of the readings that ask the assistant for something ask for it, and it makes no likely goal "
           "costlier" +
           (d.request_leaves_principal_a_step ? " but by a step of the principal's own with what it gives them" : "") +
           "); this is the first step of the assistant's plan for it";
  }
  if (d.broke_tie)
    return "tied with the best expected value (" + with_value("best", best < d.values.size() ? d.values[best] : 0.0) +
           "); this one carries out the request \"" + d.request_command + "\"";
  if (d.unanimous) return "every likely goal's plan takes this action next";
  std::string why = "highest expected value over the goal posterior (" + with_value("value", value_of(d.action));
  if (waited >= 0 && d.action != waited && !std::isnan(value_of(waited)) && value_of(waited) > value_of(d.action))
    return "both agents waited last round, so not waiting again: the best other action (" +
           with_value("value", value_of(d.action)) + ", " + with_value("waiting", value_of(waited)) + ")";
  return why + ")";
}

// The Q_MDP choice at timestep t: the common best action when
// every hypothesis above the threshold agrees, else the argmax of the
// weighted Q-values, dead ends (or, with QaFloor::Horizon, every value)
// floored at the cost of waiting to the horizon. The weighted values are
// computed for a unanimous choice too (explanations read them).
Decision decide_qmdp(const AssistSetup& setup, ActionId assistant_wait, const std::vector<Hypothesis>& belief,
                     const State& s, int t, bool stalled,
                     const std::vector<State>* since_instruction = nullptr) {
  const pddl::Task& task = *setup.task;
  std::vector<const Hypothesis*> live;
  const double cut = live_threshold(belief, setup.weight_threshold);
  for (auto& h : belief)
    if (h.weight >= cut) live.push_back(&h);
  std::optional<ActionId> common;
  bool all_same = true;
  std::vector<std::vector<search::QValue>> qvals;  // per live hypothesis, computed once
  for (const Hypothesis* h : live) {
    if (setup.refine) h->policy->refine(s, setup.refine_options);
    qvals.push_back(h->policy->q_values(s));
    auto b = h->policy->best_action(s, qvals.back());
    if (!b || (common && *common != *b)) all_same = false;
    if (b && !common) common = b;
  }
  // After a round of waits the assistant's own wait is not a candidate
  // (AssistSetup::restless_assistant), unless it is the only action.
  const bool restless = setup.restless_assistant && stalled;
  if (restless && common && *common == assistant_wait) all_same = false;
  Decision d;
  d.unanimous = all_same && common;
  const bool request_rule = setup.rule == AssistRule::Request && !setup.salient_args.empty() &&
                            std::any_of(live.begin(), live.end(),
                                        [](const Hypothesis* h) { return h->request && !h->request->empty(); });
  d.candidates = task.applicable_actions(s);
  const auto& acts = d.candidates;
  std::vector<double>& qa = d.values;
  qa.assign(acts.size(), 0.0);
  std::vector<std::vector<double>> floored(live.size(), std::vector<double>(acts.size()));  // per live hypothesis
  for (size_t k = 0; k < live.size(); ++k) {
    const Hypothesis* h = live[k];
    const auto& qs = qvals[k];
    const auto& spec = h->policy->spec();
    double wait_cost = spec.cost(assistant_wait);
    for (size_t i = 0; i < acts.size(); ++i) {
      const double floor = -((setup.horizon - t) * wait_cost + spec.cost(acts[i]));
      const double q = setup.qa_floor == QaFloor::Horizon ? std::max(qs[i].q, floor)
                                                           : (qs[i].q == -kInf ? floor : qs[i].q);
      floored[k][i] = q;
      qa[i] += h->weight * q;
    }
  }
  if (acts.empty()) throw InputError("no action is applicable in the assistance state");
  auto excluded = [&](size_t i) { return restless && acts[i] == assistant_wait && acts.size() > 1; };
  size_t best = excluded(0) ? 1 : 0;
  for (size_t i = best + 1; i < acts.size(); ++i)
    if (!excluded(i) && qa[i] > qa[best]) best = i;
  d.action = d.unanimous ? *common : acts[best];
  if (request_rule) {
    if (auto c = committed_request(setup, live, s, since_instruction)) {
      d.action = c->action;
      d.followed_request = true;
      d.request_command = c->command;
      d.request_share = c->share;
      d.request_leaves_principal_a_step = c->leaves_principal_a_step;
    }
  }
  if (request_rule && !d.followed_request) {
    // Ties at the best value go to the action whose continuation (each
    // hypothesis' own plan after it) carries out most of the request.
    // The tolerance in cost units: a share of the cheapest candidate's cost
    // under the most probable hypothesis.
    const Hypothesis* top = *std::max_element(live.begin(), live.end(),
                                              [](const Hypothesis* a, const Hypothesis* b) { return a->weight < b->weight; });
    double cheapest = kInf;
    for (ActionId a : acts)
      if (const double c = top->policy->spec().cost(a); c > 0) cheapest = std::min(cheapest, c);
    const double tol = setup.tie_tolerance * (cheapest < kInf ? cheapest : 1.0);
    // A tie is a choice that matters little whichever goal is true: the
    // expected value within tol of the best, and also the belief-weighted
    // mean of |Q_h(a) - Q_h(best)| (values that only average out, one goal's
    // gain against another's loss, are not a tie).
    double live_weight = 0;
    for (const Hypothesis* h : live) live_weight += h->weight;
    auto spread = [&](size_t i) {
      double v = 0;
      for (size_t k = 0; k < live.size(); ++k) v += live[k]->weight * std::abs(floored[k][i] - floored[k][best]);
      return live_weight > 0 ? v / live_weight : 0.0;
    };
    // Doing what was asked may cost the assistant its own effort: where the
    // cheapest plan leaves a requested fetch to the principal, acting
    // instead of waiting is worse by the gap between the assistant's
    // cheapest action and its no-op at every step. Actions behind by at
    // most that gap more ("widened") are candidates too, but win only by
    // carrying out more of the request, never by nearness alone.
    const double wait_cost = top->policy->spec().cost(assistant_wait);
    double cheapest_act = kInf;
    for (ActionId a : acts)
      if (a != assistant_wait) cheapest_act = std::min(cheapest_act, top->policy->spec().cost(a));
    const double effort = cheapest_act < kInf ? std::max(0.0, cheapest_act - wait_cost) : 0.0;
    std::vector<size_t> tied;
    std::vector<char> widened(acts.size(), 0);
    for (size_t i = 0; i < acts.size(); ++i) {
      if (excluded(i)) continue;
      if (qa[i] >= qa[best] - tol && spread(i) <= tol) {
        tied.push_back(i);
      } else if (effort > 0 && qa[i] >= qa[best] - tol - effort && spread(i) <= tol + effort) {
        tied.push_back(i);
        widened[i] = 1;
      }
    }
    if (tied.size() > 1) {
      const RequestMatcher match(setup);
      // Request scores closer than this are noise of the sampled
      // continuations; nearness to the request decides between them.
      // (0.02 and 0.05 gave the same dev results; exact comparison lost the
      // lab's dev precision 0.85 -> 0.76.)
      constexpr double kScoreMargin = 0.02;
      search::TiedRolloutOptions tied_options;
      tied_options.max_steps = std::max(0, setup.horizon - t);
      tied_options.max_plans = 4;
      tied_options.refine = false;
      d.request_scores.assign(acts.size(), std::numeric_limits<double>::quiet_NaN());
      for (size_t i : tied) {
        const State next = task.apply(s, acts[i]);
        double v = 0;
        for (const Hypothesis* h : live) {
          if (!h->request || h->request->empty()) continue;
          // Over the equally good continuations, ties broken uniformly: an
          // action that leaves the request to chance after it scores less
          // than one that begins carrying it out.
          for (const search::WeightedRollout& r : search::tied_rollouts(*h->policy, next, tied_options, setup.refine_options)) {
            std::vector<ActionId> plan{acts[i]};
            plan.insert(plan.end(), r.actions.begin(), r.actions.end());
            v += h->weight * r.weight * match.score(*h->request, plan);
          }
        }
        d.request_scores[i] = v;
      }
      // Where the continuations do not tell the candidates apart, the one
      // that brings what was asked nearest wins: h_max, from the state it
      // leads to, of what the requested assistant actions add.
      std::vector<double> distance(acts.size(), 0.0);
      for (const Hypothesis* h : live) {
        if (!h->request) continue;
        for (const RequestedCommand& c : *h->request) {
          std::string goal;
          for (ActionId a : c.assistant_part)
            for (int bit : task.action(a).eff.add) {
              const std::string atom = task.atom_str(bit);
              if (atom.rfind("(" + setup.turn_predicate + " ", 0) != 0) goal += " " + atom;
            }
          if (goal.empty()) continue;
          auto spec = std::make_shared<model::Specification>(setup.task, "(and" + goal + ")",
                                                             h->policy->spec().profile());
          heuristics::HMaxHeuristic hmax;
          hmax.prepare(*spec, s);
          for (size_t i : tied) {
            const double e = hmax.estimate(task.apply(s, acts[i]).data());
            distance[i] += h->weight * c.probability * (std::isfinite(e) ? e : 1e6);
          }
        }
      }
      auto better = [&](size_t i, size_t j) {
        if (d.request_scores[i] > d.request_scores[j] + kScoreMargin) return true;
        if (widened[i]) return false;
        return d.request_scores[i] > d.request_scores[j] - kScoreMargin && distance[i] < distance[j] - 1e-9;
      };
      size_t pick = tied.front();
      for (size_t i : tied)
        if (!widened[i]) { pick = i; break; }
      for (size_t i : tied)
        if (better(i, pick)) pick = i;
      const size_t chosen = static_cast<size_t>(std::find(acts.begin(), acts.end(), d.action) - acts.begin());
      const bool chosen_tied = std::find(tied.begin(), tied.end(), chosen) != tied.end();
      if (!chosen_tied || better(pick, chosen)) {
        d.broke_tie = acts[pick] != d.action;
        d.action = acts[pick];
      }
      if (d.broke_tie) {
        // The command that weighs most behind the choice, for explanations.
        std::map<std::string, double> by_text;
        for (const Hypothesis* h : live)
          if (h->request)
            for (const RequestedCommand& c : *h->request) by_text[c.text] += h->weight * c.probability;
        double top = -1;
        for (const auto& [text, w] : by_text)
          if (w > top) {
            top = w;
            d.request_command = text;
          }
      }
    }
  }
  d.reason = qmdp_reason(d, acts, best, restless ? assistant_wait : -1);
  if (debug_qmdp()) {
    // CLIPS_DEBUG_QMDP=1: each contested decision, per live hypothesis.
    std::fprintf(stderr, "qmdp t=%d choose %s\n", t, task.action_name(acts[best]).c_str());
    for (size_t k = 0; k < live.size(); ++k) {
      std::fprintf(stderr, "  w=%.3f %s:", live[k]->weight, live[k]->policy->spec().goal_text().c_str());
      for (const auto& q : qvals[k]) std::fprintf(stderr, " %s=%.2f", task.action_name(q.action).c_str(), q.q);
      std::fprintf(stderr, "\n");
    }
    for (size_t i = 0; i < acts.size(); ++i) std::fprintf(stderr, "  QA %s=%.3f\n", task.action_name(acts[i]).c_str(), qa[i]);
  }
  return d;
}

ActionId find_wait(const AssistSetup& setup, const std::string& agent) {
  return setup.turns().noop(*setup.task, agent);  // InputError naming the no-op action
}

// Shared machinery of one simulated episode.
std::string explain_tie(const pddl::Task& task, const Decision& d, int t) {
  std::string out = "step " + std::to_string(t) + ": tied";
  for (size_t i = 0; i < d.candidates.size(); ++i) {
    if (i >= d.request_scores.size() || std::isnan(d.request_scores[i])) continue;
    char buf[96];
    std::snprintf(buf, sizeof buf, " (value %.3f, request %.3f)", i < d.values.size() ? d.values[i] : 0.0,
                  d.request_scores[i]);
    out += " " + task.action_name(d.candidates[i]) + buf;
  }
  out += "; took " + task.action_name(d.action);
  if (d.broke_tie) out += ", for the request " + d.request_command;
  return out;
}

struct Episode {
  const AssistSetup& setup;
  const pddl::Task& task;
  pddl::Task::AtomRef principal_active;
  ActionId assistant_wait = -1, principal_wait = -1;
  // Completed-plan states -> their indices j, ascending (a state recurs in
  // the plan when both agents wait in turn).
  search::StateMap<std::vector<int>> trajectory;
  std::string assistant, principal;

  explicit Episode(const AssistSetup& s)
      : setup(s), task(*s.task), trajectory(s.task->num_words()), assistant(s.assistant), principal(s.principal) {
    principal_active = s.turns().turn_atom(task, principal);
    assistant_wait = find_wait(s, assistant);
    principal_wait = find_wait(s, principal);
    State cur = setup.start;
    for (size_t j = 0; j < setup.completed.size(); ++j) {
      trajectory[cur.data()].push_back(static_cast<int>(j));
      if (!task.applicable(setup.completed[j], cur.data())) break;
      cur = task.apply(cur, setup.completed[j]);
    }
  }

  bool principal_turn(const State& s) const { return task.test(s, principal_active); }

  // The impatient principal (AssistSetup::impatient_principal): whether the
  // principal's turn in `s` comes after a round in which nothing changed.
  struct Patience {
    std::optional<State> last;  // the state of the principal's previous turn
    bool stuck(const State& s) const { return last && last->words == s.words; }
  };
  ActionId wait_of_active(const State& s) const { return principal_turn(s) ? principal_wait : assistant_wait; }

  // Which completed-plan steps the principal has taken by rule 1, one flag
  // per step; a fresh one per simulated run.
  std::vector<bool> fresh_steps() const { return std::vector<bool>(setup.completed.size(), false); }

  // The paper's simulated principal: follow the completed plan where the state matches,
  // else the true goal's joint policy, else wait.
  // Rule 1 takes each step j of the completed plan at most once (`taken`):
  // the smallest untaken j whose state equals s_h. When the assistant does
  // not do what the recording did next (typically it waits where the
  // recorded robot moved), the joint state can come back to one where the
  // principal already took step j — a recorded wait, or a move the policy
  // then undoes. Taking step j again replays the same turn for ever (both
  // agents waiting until the horizon, or a back-and-forth); the recording
  // says nothing more about that state, so the principal plans (rule 2).
  // k: 1-based step of the assistance episode (t - T).
  ActionId principal_action(const search::Policy& truth, const State& s_h, bool follow_plan, std::vector<bool>& taken,
                            int k = 0) const {
    if (follow_plan) {
      if (const std::vector<int>* js = trajectory.find(s_h.data())) {
        for (int j : *js) {
          if (taken[static_cast<size_t>(j)]) continue;
          ActionId a = setup.completed[static_cast<size_t>(j)];
          if (!task.applicable(a, s_h.data())) break;
          taken[static_cast<size_t>(j)] = true;
          return a;
        }
      }
      if (setup.follow_plan_by_index && k >= 1 && k <= static_cast<int>(setup.completed.size())) {
        ActionId a = setup.completed[k - 1];
        if (task.applicable(a, s_h.data())) return a;
      }
    }
    if (truth.value(s_h) == -kInf) return wait_of_active(s_h);
    auto a = truth.best_action(s_h);
    return a ? *a : wait_of_active(s_h);
  }

  // The episode's states before the current one (the instruction was heard
  // in the observed prefix, so all of them follow it).
  mutable std::vector<State> visited;
  // The assistant's turn at s, decided by `decide` on `belief`; what the
  // request rule did is kept for AssistResult::ties.
  ActionId decide_with(const Decide& decide, const std::vector<Hypothesis>& belief, const State& s, int t,
                       bool stalled) const {
    const Decision d = decide(DecisionInput{setup, belief, s, t, stalled, &visited});
    if (d.followed_request)
      tie_notes.push_back("step " + std::to_string(t) + ": " + d.reason + "; took " + task.action_name(d.action));
    else if (!d.request_scores.empty())
      tie_notes.push_back(explain_tie(*setup.task, d, t));
    return d.action;
  }
  // The request rule's decisions in the episode, in order (AssistResult::ties).
  mutable std::vector<std::string> tie_notes;

  // log P_coop(a|s) - log P_rand(a|s): Boltzmann (T = 1) under the true
  // policy versus uniform over the assistant's available actions.
  double coop_increment(const search::Policy& truth, const State& s, ActionId a) const {
    if (setup.trusts_own_plan && recorded(s, a)) return std::max(0.0, boltzmann_increment(truth, s, a));
    return boltzmann_increment(truth, s, a);
  }
  // Whether the completed plan takes `a` in `s` (AssistSetup::trusts_own_plan).
  bool recorded(const State& s, ActionId a) const {
    if (const std::vector<int>* js = trajectory.find(s.data()))
      for (int j : *js)
        if (setup.completed[static_cast<size_t>(j)] == a) return true;
    return false;
  }
  double boltzmann_increment(const search::Policy& truth, const State& s, ActionId a) const {
    auto qs = truth.q_values(s);
    double mx = -kInf;
    for (auto& q : qs) mx = std::max(mx, q.q);
    if (qs.empty()) return 0;
    double z = 0, qa = -kInf;
    for (auto& q : qs) {
      if (q.q > -kInf) z += std::exp(q.q - mx);
      if (q.action == a) qa = q.q;
    }
    double logp = (qa == -kInf || mx == -kInf) ? -kInf : (qa - mx) - std::log(z);
    return logp + std::log(static_cast<double>(qs.size()));
  }

  void collect_option(ActionId a, std::map<std::string, double>& opts) const {
    if (!setup.option_of) return;
    if (auto o = setup.option_of(a)) opts[*o] = 1.0;
  }
};

void finish(const AssistSetup& setup, const model::Specification& truth, AssistResult& r) {
  r.plan_length = static_cast<double>(r.plan.size()) + r.noops;
  r.plan_cost = plan_cost(truth, r.plan) + r.noops * setup.noop_cost;
  r.human_cost = human_cost(truth, r.plan, setup.principal) + r.noops * setup.noop_cost;
  r.success = r.goal_reached ? 1.0 : 0.0;
}

// What the simulated principal does once it stops trusting the assistant
// (log P_coop - log P_rand of the assistant's actions below log 0.1): the
// three evaluations of the spec differ only there.
enum class Distrust {
  TakeOver,      // offline Q_MDP: plans as if the assistant were frozen and acts on every turn
  PlanAlone,     // online Q_MDP: plans as if the assistant were frozen, on its own turns only
  FreezeWorld,   // pi-bar per hypothesis: the assistant is frozen in the world; the principal acts on every turn
  Never,         // a scripted assistant: trusted to the script's end, then as TakeOver
};

// The one episode loop of the simulated assistance: from setup.start to the
// horizon or the true goal, the principal simulated by `truth` (refined as
// it goes), the assistant's turns decided by `decide(s, t, plan so far)`,
// and `seen(s, a)` told of every action but the one that reaches the goal.
// `done()`: the assistant has nothing more to do (a script used up), so the
// principal takes over.
template <typename Decide, typename Seen, typename Done>
AssistResult run_episode(Episode& ep, search::Policy& truth, const model::Specification& tspec, Distrust distrust,
                         Decide&& decide, Seen&& seen, Done&& done) {
  const AssistSetup& setup = ep.setup;
  const pddl::Task& task = ep.task;
  AssistResult r;
  double coop = 0;
  bool solo = false;
  State s = setup.start;
  std::vector<bool> taken = ep.fresh_steps();
  Episode::Patience patience;
  for (int t = setup.observed_steps + 1; t <= setup.horizon; ++t) {
    const int k = t - setup.observed_steps;
    ActionId a;
    if (distrust == Distrust::PlanAlone) {
      if (setup.refine) truth.refine(s, setup.refine_options);
      if (ep.principal_turn(s)) {
        const bool stuck = setup.impatient_principal && patience.stuck(s);
        patience.last = s;
        if (coop < -kLog10 || stuck) {
          const State s_h = model::freeze(task, s, setup.assistant);
          if (setup.refine) truth.refine(s_h, setup.refine_options);
          a = ep.principal_action(truth, s_h, false, taken);
        } else {
          a = ep.principal_action(truth, s, true, taken, k);
        }
      } else {
        a = decide(s, t, r);
        coop += ep.coop_increment(truth, s, a);
        ep.collect_option(a, r.options);
      }
    } else {
      // Trust lost is for good: the assistant, not acting any more, cannot win it back.
      if (!solo && ((distrust != Distrust::Never && coop < -kLog10) || done())) {
        solo = true;
        if (distrust == Distrust::FreezeWorld) s = model::freeze(task, s, setup.assistant);
      }
      const bool stuck = !solo && setup.impatient_principal && ep.principal_turn(s) && patience.stuck(s);
      const bool frozen_view = stuck || (solo && distrust != Distrust::FreezeWorld);
      const State s_h = frozen_view ? model::freeze(task, s, setup.assistant) : s;
      if (setup.refine) truth.refine(s_h, setup.refine_options);
      if (ep.principal_turn(s) || solo) {
        if (ep.principal_turn(s)) patience.last = s;
        a = ep.principal_action(truth, s_h, !solo && !stuck, taken, k);
      } else {
        a = decide(s, t, r);
        coop += ep.coop_increment(truth, s, a);
        ep.collect_option(a, r.options);
      }
    }
    r.plan.push_back(a);
    if (setup.rule == AssistRule::Request) ep.visited.push_back(s);
    const State pre = s;
    s = task.apply(s, a);
    if (tspec.is_goal(s)) {
      r.goal_reached = true;
      break;
    }
    seen(pre, a);
  }
  finish(setup, tspec, r);
  r.ties = std::move(ep.tie_notes);
  ep.tie_notes.clear();
  return r;
}

}  // namespace

AssistResult offline_episode(const AssistSetup& setup, std::vector<Hypothesis> belief, int true_hypothesis,
                             const Decide& decide) {
  Episode ep(setup);
  search::Policy truth = *belief.at(true_hypothesis).policy;  // a copy: the principal's own planner
  for (auto& h : belief) h.policy = std::make_shared<search::Policy>(*h.policy);  // never touch the caller's
  std::vector<double> seconds;
  AssistResult r = run_episode(
      ep, truth, truth.spec(), Distrust::TakeOver,
      [&](const State& s, int t, const AssistResult& so_far) {
        const auto d0 = std::chrono::steady_clock::now();
        const ActionId a = ep.decide_with(decide, belief, s, t, round_of_waits(setup, so_far.plan));
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - d0).count());
        return a;
      },
      [](const State&, ActionId) {}, [] { return false; });
  r.decision_seconds = std::move(seconds);
  return r;
}

AssistResult qmdp_offline(const AssistSetup& setup, std::vector<Hypothesis> belief, int true_hypothesis) {
  return offline_episode(setup, std::move(belief), true_hypothesis, [](const DecisionInput& in) {
    return qmdp_decision(in.setup, in.hypotheses, in.state, in.t, in.stalled, in.since_instruction);
  });
}

bool assistant_turn(const AssistSetup& setup, const State& s) {
  return !setup.turns().is_turn_of(*setup.task, s, setup.principal);
}

AssistResult online_episode(const AssistSetup& setup, OnlineBelief& belief,
                            std::shared_ptr<const model::Specification> true_spec,
                            std::shared_ptr<heuristics::Heuristic> true_heuristic, const Decide& decide) {
  Episode ep(setup);
  search::Policy truth(true_spec, std::move(true_heuristic));  // fresh, refined as it goes
  return run_episode(
      ep, truth, *true_spec, Distrust::PlanAlone,
      [&](const State& s, int t, const AssistResult& so_far) {
        return ep.decide_with(decide, belief.hypotheses(), s, t, round_of_waits(setup, so_far.plan));
      },
      [&](const State& pre, ActionId a) { belief.observe(pre, a); }, [] { return false; });
}

AssistResult pibar_mdp(const AssistSetup& setup, std::vector<Hypothesis> belief, int true_hypothesis) {
  Episode ep(setup);
  const model::Specification& tspec = belief.at(true_hypothesis).policy->spec();
  AssistResult mean;
  int remaining = setup.horizon - setup.observed_steps;
  double best_w = -1;
  // Options: pure greedy rollouts of every hypothesis (no threshold).
  for (auto& h : belief) {
    auto roll = h.policy->rollout(setup.start, remaining);
    std::map<std::string, double> seen;
    for (ActionId a : roll) ep.collect_option(a, seen);
    for (auto& [o, v] : seen) mean.options[o] += h.weight * v;
  }
  const double cut = live_threshold(belief, setup.weight_threshold);
  for (size_t hi = 0; hi < belief.size(); ++hi) {
    const Hypothesis& h = belief[hi];
    AssistResult run;
    if (h.weight < cut) {
      run.noops = remaining;  // the reference's no-op plan for ignored hypotheses
      finish(setup, tspec, run);
    } else {
      // The episode had this hypothesis been the assistant's only one.
      search::Policy truth = *belief[true_hypothesis].policy;
      search::Policy mine = *h.policy;
      ep.visited.clear();
      run = run_episode(
          ep, truth, tspec, Distrust::FreezeWorld,
          [&](const State& s, int, const AssistResult&) {
            if (setup.refine) mine.refine(s, setup.refine_options);
            auto b = mine.value(s) > -kInf ? mine.best_action(s) : std::nullopt;
            return b ? *b : ep.assistant_wait;
          },
          [](const State&, ActionId) {}, [] { return false; });
    }
    mean.plan_length += h.weight * run.plan_length;
    mean.plan_cost += h.weight * run.plan_cost;
    mean.human_cost += h.weight * run.human_cost;
    mean.success += h.weight * run.success;
    if (h.weight > best_w) {
      best_w = h.weight;
      mean.plan = run.plan;
      mean.noops = run.noops;
    }
  }
  mean.goal_reached = mean.success >= 0.5;
  return mean;
}

AssistResult scripted_episode(const AssistSetup& setup, search::Policy truth, size_t length,
                              const std::function<ActionId(const State&, size_t)>& play) {
  Episode ep(setup);
  size_t next = 0;
  return run_episode(
      ep, truth, truth.spec(), Distrust::Never, [&](const State& s, int, const AssistResult&) { return play(s, next++); },
      [](const State&, ActionId) {}, [&] { return next >= length; });
}

bool round_of_waits(const AssistSetup& setup, const std::vector<ActionId>& actions) {
  const size_t n = actions.size();
  return n >= 2 && actions[n - 1] == setup.turns().noop(*setup.task, setup.principal) &&
         actions[n - 2] == setup.turns().noop(*setup.task, setup.assistant);
}

Decision qmdp_decision(const AssistSetup& setup, const std::vector<Hypothesis>& belief, const pddl::State& s, int t,
                       bool stalled, const std::vector<pddl::State>* since_instruction) {
  return decide_qmdp(setup, find_wait(setup, setup.assistant), belief, s, t, stalled, since_instruction);
}

Decision pibar_decision(const AssistSetup& setup, const std::vector<Hypothesis>& belief, const pddl::State& s) {
  const pddl::Task& task = *setup.task;
  Decision d;
  d.candidates = task.applicable_actions(s);
  d.values.assign(d.candidates.size(), 0.0);
  std::optional<ActionId> common;
  bool all_same = true;
  double total = 0;
  const double cut = live_threshold(belief, setup.weight_threshold);
  for (const Hypothesis& h : belief) {
    if (h.weight < cut) continue;
    if (setup.refine) h.policy->refine(s, setup.refine_options);
    // As in pibar_mdp: a hypothesis with no way to its goal waits.
    auto b = h.policy->value(s) > -kInf ? h.policy->best_action(s) : std::nullopt;
    const ActionId a = b ? *b : find_wait(setup, setup.assistant);
    if (common && *common != a) all_same = false;
    if (!common) common = a;
    for (size_t i = 0; i < d.candidates.size(); ++i)
      if (d.candidates[i] == a) d.values[i] += h.weight;
    total += h.weight;
  }
  if (total > 0)
    for (double& v : d.values) v /= total;
  size_t best = 0;
  for (size_t i = 1; i < d.candidates.size(); ++i)
    if (d.values[i] > d.values[best]) best = i;
  if (d.candidates.empty()) throw InputError("no action is applicable in the assistance state");
  d.action = d.candidates[best];
  d.unanimous = all_same && common.has_value();
  d.reason = d.unanimous ? "every likely goal's plan takes this action next"
                         : with_value("the action the goal posterior's policies take most often (probability",
                                      d.values[best]) + ")";
  return d;
}

}  // namespace clips::assist
