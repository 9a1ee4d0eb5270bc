#include "search/tied_rollouts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace clips::search {

namespace {

struct Pending {
  pddl::State state;
  std::vector<pddl::ActionId> actions;
  double weight = 1;
};

// A REFINE of s restricted to the actions whose Q, as the policy holds it
// now, is within `slack` of the best: a lookahead from each of their
// successors (all of them when slack is infinite).
void refine_near_best(Policy& policy, const pddl::State& s, const SearchOptions& o, double slack) {
  if (!std::isfinite(slack)) {
    policy.refine(s, o);
    return;
  }
  const std::vector<QValue> qs = policy.q_values(s);
  double best = -std::numeric_limits<double>::infinity();
  for (const QValue& q : qs) best = std::max(best, q.q);
  if (!std::isfinite(best)) {
    policy.refine(s, o);
    return;
  }
  for (const QValue& q : qs)
    if (q.q >= best - slack) policy.refine_toward(s, q.action, o);
}

}  // namespace

std::vector<WeightedRollout> tied_rollouts(Policy& policy, const pddl::State& s, const TiedRolloutOptions& options,
                                           const SearchOptions& refine) {
  const model::Specification& spec = policy.spec();
  const pddl::Task& task = spec.task();
  StateMap<char> refined(task.num_words());
  int refines_left = options.max_refined_states;
  std::vector<WeightedRollout> out;
  std::vector<Pending> stack;
  stack.push_back({s, {}, 1.0});
  while (!stack.empty()) {
    Pending cur = std::move(stack.back());
    stack.pop_back();
    pddl::State x = std::move(cur.state);
    std::vector<pddl::ActionId> path = std::move(cur.actions);
    double w = cur.weight;
    while (static_cast<int>(path.size()) < options.max_steps && !spec.is_goal(x)) {
      const bool may_branch = static_cast<int>(path.size()) < options.branch_depth;
      if (options.refine && may_branch && refines_left > 0 && !refined.contains(x.data())) {
        refined[x.data()] = 1;
        --refines_left;
        SearchOptions o = refine;
        if (!path.empty()) o.max_nodes = std::min(refine.max_nodes, options.branch_max_nodes);
        refine_near_best(policy, x, o, options.refine_slack);
      }
      const std::vector<QValue> qs = policy.q_values(x);
      const auto best = policy.best_action(x, qs);
      if (!best) break;
      if (may_branch && (!options.refine || refined.contains(x.data()))) {
        double q_best = -std::numeric_limits<double>::infinity();
        for (const QValue& q : qs)
          if (q.action == *best) q_best = q.q;
        std::vector<pddl::ActionId> tied;
        if (q_best > -std::numeric_limits<double>::infinity())
          for (const QValue& q : qs)
            if (q.action != *best && q.q >= q_best - options.tolerance) tied.push_back(q.action);
        // Room for the alternatives: the rollouts done, those waiting and this one.
        const long room = static_cast<long>(options.max_plans) - static_cast<long>(out.size() + stack.size() + 1);
        if (!tied.empty() && room > 0) {
          if (static_cast<long>(tied.size()) > room) tied.resize(static_cast<size_t>(room));
          const double share = w / static_cast<double>(tied.size() + 1);
          // Pushed in reverse so the stack visits them in action order.
          for (auto it = tied.rbegin(); it != tied.rend(); ++it) {
            Pending alt{task.apply(x, *it), path, share};
            alt.actions.push_back(*it);
            stack.push_back(std::move(alt));
          }
          w = share;
        }
      }
      path.push_back(*best);
      x = task.apply(x, *best);
    }
    out.push_back({w, std::move(path)});
  }
  double total = 0;
  for (const auto& r : out) total += r.weight;
  if (total > 0)
    for (auto& r : out) r.weight /= total;
  return out;
}

}  // namespace clips::search
