#include "search/rtaa.hpp"

#include <cmath>

namespace clips::search {

using model::kInf;

Policy::Policy(std::shared_ptr<const model::Specification> spec, std::shared_ptr<heuristics::Heuristic> h)
    : spec_(std::move(spec)),
      h_(std::move(h)),
      tree_(spec_->task().num_words()),
      table_(spec_->task().num_words()) {}

double Policy::value(const uint64_t* s) const {
  if (const double* v = find_value(s)) return *v;
  return -h_->estimate(s);
}

double Policy::learned_estimate(const uint64_t* x) {
  Entry& e = table_[x];
  if (e.has_v) return -e.v;
  if (!e.has_h) {
    e.h = h_->estimate(x);  // does not touch table_, so `e` stays valid
    e.has_h = true;
  }
  return e.h;
}

namespace {

// One workspace per thread: lookahead searches reuse its buffers. A nested
// refine on the same thread (not expected) falls back to a private one.
struct ThreadWorkspace {
  SearchWorkspace ws;
  bool busy = false;
};
thread_local ThreadWorkspace tls_workspace;

}  // namespace

RefineStats Policy::refine(const pddl::State& s, const SearchOptions& opts_in) {
  RefineStats st;
  const pddl::Task& task = spec_->task();
  h_->prepare(*spec_, s);  // pruning sets from this call's starting state
  if (h_->estimates_depend_on_root())
    for (Entry& e : table_.values()) e.has_h = false;  // cached estimates may be stale now
  std::optional<SearchWorkspace> own;
  SearchWorkspace* ws = &tls_workspace.ws;
  if (tls_workspace.busy) ws = &own.emplace();
  else tls_workspace.busy = true;
  struct Release {
    bool on;
    ~Release() {
      if (on) tls_workspace.busy = false;
    }
  } release{ws == &tls_workspace.ws};
  SearchOptions opts = opts_in;
  opts.extra_goal = [this](const uint64_t* x) { return tree_.contains(x); };
  // Lookahead heuristic: the learned value where known, else H.
  struct Learned : heuristics::Heuristic {
    Policy* p;
    explicit Learned(Policy* pp) : p(pp) {}
    std::string name() const override { return "learned"; }
    bool admissible() const override { return p->h_->admissible(); }
    bool consistent() const override { return false; }
    void prepare(const model::Specification&, const pddl::State&) override {}
    double estimate(const uint64_t* x) override { return p->learned_estimate(x); }
    bool prunes() const override { return p->h_->prunes(); }
    bool keep(pddl::ActionId a) const override { return p->h_->keep(a); }
  } learned(this);

  std::vector<uint64_t> child(task.num_words());
  pddl::State child_state;
  double best = -kInf;
  for (pddl::ActionId a : task.applicable_actions(s)) {
    task.apply(a, s.data(), child.data());
    if (const double* v = find_value(child.data()); v && *v == -kInf) continue;
    if (spec_->is_goal(child.data())) {
      set_value(child.data(), 0);
    } else {
      child_state.words.assign(child.begin(), child.end());
      const SearchResult& r = astar(*spec_, learned, child_state, opts, *ws);
      ++st.searches;
      st.expanded += r.expanded;
      update(r);
    }
    best = std::max(best, -spec_->cost(a) + value(child.data()));
  }
  set_value(s.data(), best);
  return st;
}

void Policy::update(const SearchResult& r) {
  const StateRegistry& reg = *r.registry;
  if (r.status == SearchStatus::Failure) {
    for (int id = 0; id < reg.size(); ++id) set_value(reg.get(id), -kInf);
    return;
  }
  int t = r.terminal;
  double h_t = r.nodes[t].h;
  double f_t = r.nodes[t].g + h_t;
  set_value(reg.get(t), -h_t);
  for (int id = 0; id < reg.size(); ++id) {
    const SearchNode& n = r.nodes[id];
    if (n.open && id != t) continue;  // frontier nodes keep their values
    if (id == t) continue;
    set_value(reg.get(id), -(f_t - n.g));
  }
  if (r.status == SearchStatus::Success) {
    // Store the path root..t: each node records the action toward the goal.
    for (int id = t; r.nodes[id].parent >= 0; id = r.nodes[id].parent)
      tree_.try_emplace(reg.get(r.nodes[id].parent), r.nodes[id].action);
  }
}

std::vector<QValue> Policy::q_values(const pddl::State& s) const {
  const pddl::Task& task = spec_->task();
  std::vector<QValue> out;
  std::vector<uint64_t> child(task.num_words());
  for (pddl::ActionId a : task.applicable_actions(s)) {
    task.apply(a, s.data(), child.data());
    double v = spec_->is_goal(child.data()) ? (has_value(child.data()) ? *find_value(child.data()) : 0.0)
                                            : value(child.data());
    out.push_back({a, -spec_->cost(a) + v});
  }
  return out;
}

std::optional<pddl::ActionId> Policy::best_action(const pddl::State& s) const {
  if (const pddl::ActionId* a = tree_.find(s.data()); a && spec_->task().applicable(*a, s.data())) return *a;
  return best_action(s, q_values(s));
}

std::optional<pddl::ActionId> Policy::best_action(const pddl::State& s, const std::vector<QValue>& qs) const {
  if (const pddl::ActionId* a = tree_.find(s.data()); a && spec_->task().applicable(*a, s.data())) return *a;
  std::optional<pddl::ActionId> best;
  double bq = -kInf;
  for (const QValue& q : qs)
    if (q.q > bq) {
      bq = q.q;
      best = q.action;
    }
  return best;
}

std::vector<pddl::ActionId> Policy::rollout(const pddl::State& start, int max_steps) const {
  std::vector<pddl::ActionId> plan;
  pddl::State s = start;
  for (int i = 0; i < max_steps; ++i) {
    if (spec_->is_goal(s)) break;
    auto a = best_action(s);
    if (!a) break;
    plan.push_back(*a);
    s = spec_->task().apply(s, *a);
    if (spec_->is_goal(s)) break;
  }
  return plan;
}

}  // namespace clips::search
