#pragma once
// Real-Time Adaptive A* with path reuse: a Policy is the
// "solution" for one specification. It holds
//   * a value table V over states (values are NEGATIVE costs; a missing entry
//     means -H(s) from the heuristic),
//   * a reusable tree: states on previously found goal paths -> next action.
// refine(s) runs one lookahead A* from each successor of s and updates V for
// every interior node of each search tree; afterwards the Q-values of all
// applicable actions in s are fresh. Policies are copyable values (the
// assistance phase keeps refining copies of the inference policies).
#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "search/astar.hpp"
#include "search/state_graph.hpp"

namespace clips::search {

struct QValue {
  pddl::ActionId action;
  double q;  // -(cost(a) + cost-to-go of the successor); -inf for dead ends
};

struct RefineStats {
  size_t searches = 0, expanded = 0;
  // Searches ended by max_nodes or max_time: they learned values from a
  // partial search, so results depend on the budget.
  size_t stopped_by_budget = 0;
};

class Policy {
 public:
  // `graph` holds the states and successors this policy searches; policies
  // over the same task may share one (see state_graph.hpp). Null: a graph of
  // its own.
  Policy(std::shared_ptr<const model::Specification> spec, std::shared_ptr<heuristics::Heuristic> h,
         std::shared_ptr<StateGraph> graph = nullptr);

  const model::Specification& spec() const { return *spec_; }
  std::shared_ptr<const model::Specification> spec_ptr() const { return spec_; }
  heuristics::Heuristic& heuristic() const { return *h_; }

  // V(s): table value, else -H(s).
  double value(const uint64_t* s) const;
  double value(const pddl::State& s) const { return value(s.data()); }
  bool has_value(const uint64_t* s) const { return find_value(s) != nullptr; }

  // One RTAA* policy update at s. `opts` holds the budgets.
  RefineStats refine(const pddl::State& s, const SearchOptions& opts);
  // One timestep of the policy lifecycle: refine at s, and if no
  // action is usable there afterwards, forget everything learned and refine
  // again from an empty policy. Inference and the generator's simulated
  // human both follow it, so a generated speaker plans as the observer's model does.
  RefineStats refine_step(const pddl::State& s, const SearchOptions& opts);
  // The one lookahead of refine(s) that starts at the successor of s by
  // `taken`: it learns the values along the way the agents went on, but the
  // Q-values of s's other actions stay as they were and V(s) is not set (a
  // maximum over some actions is no value). For steps whose Q-values nobody
  // reads; no reset as in refine_step (the next refine_step does that).
  RefineStats refine_toward(const pddl::State& s, pddl::ActionId taken, const SearchOptions& opts);

  // Q-values of every applicable action of the active agent in s (unfiltered,
  // in enumeration order). Reads V (or -H) of the successors; no search.
  std::vector<QValue> q_values(const pddl::State& s) const;
  // Tree action when s lies on a stored goal path, else the first action of
  // maximal Q; nullopt if every Q is -inf or nothing is applicable.
  std::optional<pddl::ActionId> best_action(const pddl::State& s) const;
  // The same, from Q-values already computed by q_values(s).
  std::optional<pddl::ActionId> best_action(const pddl::State& s, const std::vector<QValue>& qs) const;
  // Whether s lies on a stored goal path. Such a path is never changed by
  // later refinements (a tree action, once set, stays until the policy is
  // reset), so rollout(s) follows it whatever else is refined.
  bool on_stored_path(const pddl::State& s) const {
    const Entry* e = tree_entry(s.data());
    return e && spec_->task().applicable(e->tree_action, s.data());
  }
  // Greedy rollout of best_action for at most `max_steps`, stopping at the goal.
  std::vector<pddl::ActionId> rollout(const pddl::State& s, int max_steps) const;

  size_t table_size() const { return num_values_; }
  size_t tree_size() const { return tree_size_; }

 private:
  // Per state id of the graph (an id this policy never touched reads as the
  // default entry): the learned value V, the cached estimate H, the state's place
  // on the reusable tree and the cached goal test. The lookahead A* works on
  // ids, so it hashes a state only when the graph first generates it.
  struct Entry {
    // The lookahead is bound by memory latency, so an entry is kept small
    // and holds everything a generated successor needs in one cache line.
    // V(s) when has_v, else the cached estimate H(s) when has_h: once a state
    // has a learned value its estimate is never read again, so one slot holds
    // either.
    double value_or_h = 0;
    // The lookahead search that last generated this state (its epoch) and
    // its node there: the duplicate test of every generated successor.
    uint32_t epoch = 0;
    int node = 0;
    pddl::ActionId tree_action = -1;  // next action on a stored goal path; -1: not a tree node
    bool has_v = false, has_h = false;
    int8_t goal = -1;                 // cached goal test: -1 unknown, 0 no, 1 yes
  };
  struct LookaheadNode {
    int entry;
    int parent = -1;  // node index
    pddl::ActionId action = -1;
    double g = 0, h = 0;
    bool open = false;
    uint32_t version = 0;
    uint64_t counter = 0;
  };
  struct Lookahead;  // per-thread buffers (rtaa.cpp)

  // refine(s), or with only >= 0 refine_toward(s, only).
  RefineStats refine_successors(const pddl::State& s, const SearchOptions& opts, pddl::ActionId only);
  // A* from state `root` with the learned estimates, stopping at a goal or
  // tree state; then the RTAA* update of the values and tree.
  // Returns the expansions; `status` tells how the search ended.
  size_t search_and_update(int root, const SearchOptions& opts, bool prune, Lookahead& ws, SearchStatus& status);
  double learned_estimate(int id);
  bool is_goal_entry(int id);
  // Entries live in fixed-size chunks indexed by state id. The graph is
  // shared, so most ids belong to other hypotheses' searches: a flat array
  // sized to the graph zero-filled (and on growth, copied) all of them, a
  // third of a belief step's time on the paper's maps. A chunk is allocated
  // when this policy first touches one of its ids. Copies of a policy (the
  // assistance refines copies of every hypothesis' policy, for each method)
  // share chunks until one of them writes to one: the writer gets its own
  // copy of that chunk first, so every policy still behaves as a value.
  static constexpr int kEntryChunkBits = 11;
  static constexpr size_t kEntryChunk = size_t{1} << kEntryChunkBits;
  using Chunk = std::shared_ptr<Entry[]>;  // kEntryChunk entries (one indirection, as a plain array)
  static Chunk new_chunk() { return std::make_shared<Entry[]>(kEntryChunk); }
  static Chunk copy_chunk(const Chunk& c) {
    Chunk out = std::make_shared_for_overwrite<Entry[]>(kEntryChunk);
    std::copy(c.get(), c.get() + kEntryChunk, out.get());
    return out;
  }
  // The entry of state `id` for writing: allocates its chunk, or copies a
  // chunk this policy shares with a copy of it.
  Entry& entry(int id) {
    const size_t c = static_cast<size_t>(id) >> kEntryChunkBits;
    if (c >= chunks_.size()) chunks_.resize(c + 1);
    Chunk& chunk = chunks_[c];
    if (!chunk) chunk = new_chunk();
    else if (chunk.use_count() > 1) chunk = copy_chunk(chunk);
    return chunk[static_cast<std::ptrdiff_t>(static_cast<size_t>(id) & (kEntryChunk - 1))];
  }
  // The entry of state `id` for reading, if its chunk exists (an entry this
  // policy never wrote reads as the default: no value, no estimate, not in
  // any search).
  const Entry* read_entry(int id) const {
    const size_t c = static_cast<size_t>(id) >> kEntryChunkBits;
    return c < chunks_.size() && chunks_[c] ? chunks_[c].get() + (static_cast<size_t>(id) & (kEntryChunk - 1)) : nullptr;
  }
  const Entry* find_entry(const uint64_t* s) const {
    const int id = graph_->find(s);
    return id < 0 ? nullptr : read_entry(id);
  }
  template <class F>
  void for_each_entry(F&& f) {
    for (auto& chunk : chunks_) {
      if (!chunk) continue;
      if (chunk.use_count() > 1) chunk = copy_chunk(chunk);
      for (size_t i = 0; i < kEntryChunk; ++i) f(chunk[static_cast<std::ptrdiff_t>(i)]);
    }
  }
  // Estimates shared by a policy and its copies: they have the same
  // specification and heuristic, so the same H(s), and a copy refined for
  // assistance need not estimate again what the original or another copy
  // did. Per state id, NaN where unknown. Like the heuristic the copies
  // share, it is not for copies refined on different threads at once. Null
  // when the heuristic's estimates depend on the root of the refinement.
  struct SharedEstimates {
    static constexpr int kBits = 12;
    static constexpr size_t kSize = size_t{1} << kBits;
    std::vector<std::unique_ptr<double[]>> chunks;
    double get(int id) const {
      const size_t c = static_cast<size_t>(id) >> kBits;
      return c < chunks.size() && chunks[c] ? chunks[c][static_cast<size_t>(id) & (kSize - 1)]
                                            : std::numeric_limits<double>::quiet_NaN();
    }
    void set(int id, double h);
  };

  std::shared_ptr<const model::Specification> spec_;
  std::shared_ptr<heuristics::Heuristic> h_;
  std::shared_ptr<StateGraph> graph_;
  // H estimates are kept across refine() calls unless the heuristic says
  // they depend on the root prepare() was given.
  std::vector<Chunk> chunks_;
  std::shared_ptr<SharedEstimates> estimates_;
  size_t num_values_ = 0;  // entries with has_v
  size_t tree_size_ = 0;   // entries with a tree action
  uint32_t epoch_ = 0;
  const double* find_value(const uint64_t* s) const {
    const Entry* e = find_entry(s);
    return e && e->has_v ? &e->value_or_h : nullptr;
  }
  void set_value(int id, double v) {
    Entry& e = entry(id);
    if (!e.has_v) ++num_values_;
    e.has_v = true;
    e.value_or_h = v;
  }
  const Entry* tree_entry(const uint64_t* s) const {
    const Entry* e = find_entry(s);
    return e && e->tree_action >= 0 ? e : nullptr;
  }
};

}  // namespace clips::search
