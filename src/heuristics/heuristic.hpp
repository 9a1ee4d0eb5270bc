#pragma once
// Heuristics estimate the cost to reach a specification's goal from a state.
// Like Fast Downward's, each is a small class with one estimate method and
// declared properties (which tests check); like SymbolicPlanners', it has a
// precompute step per planning call (`prepare`) kept out of the hot path.
//
// A heuristic may also prune goal-irrelevant actions during search
// (the reference's action pruning): A* asks keep() for each applicable action it expands.
#include <chrono>
#include <string>

#include "model/spec.hpp"

namespace clips::heuristics {

class Heuristic {
 public:
  virtual ~Heuristic() = default;
  virtual std::string name() const = 0;
  virtual bool admissible() const = 0;
  virtual bool consistent() const = 0;
  // Called once per planning call with the specification and the state the
  // call starts from (goal-specific precomputation, pruning sets).
  virtual void prepare(const model::Specification& spec, const pddl::State& root) = 0;
  // Estimated cost-to-go; model::kInf for a recognised dead end.
  virtual double estimate(const uint64_t* state) = 0;
  double estimate(const pddl::State& s) { return estimate(s.data()); }
  // Whether estimate() can change when prepare() is called again with the
  // same specification and another root. RTAA* policies cache estimates
  // across refinements only when it cannot; the default is the safe answer.
  virtual bool estimates_depend_on_root() const { return true; }
  // Action pruning inside search (default: keep everything).
  virtual bool prunes() const { return false; }
  virtual bool keep(pddl::ActionId) const { return true; }

  // Deadlines. A search with a time limit hands its deadline to the heuristic
  // so that an estimate which is itself long (h_max over a large grounding)
  // can stop early: it then returns 0 (admissible, so never a wrong cut) and
  // reports timed_out() until the next set_deadline(). Cheap estimates may
  // ignore the deadline: the search also checks the clock between them.
  using Clock = std::chrono::steady_clock;
  void set_deadline(Clock::time_point t) {
    deadline_ = t;
    timed_out_ = false;
  }
  Clock::time_point deadline() const { return deadline_; }
  bool timed_out() const { return timed_out_; }

 protected:
  // For estimate(): true once the deadline has passed (then always true).
  bool out_of_time() {
    if (!timed_out_ && deadline_ != Clock::time_point::max() && Clock::now() >= deadline_) timed_out_ = true;
    return timed_out_;
  }

 private:
  Clock::time_point deadline_ = Clock::time_point::max();
  bool timed_out_ = false;
};

// Sets a heuristic's deadline for one scope and restores the previous one.
class ScopedDeadline {
 public:
  ScopedDeadline(Heuristic& h, Heuristic::Clock::time_point t) : h_(h), previous_(h.deadline()) {
    h_.set_deadline(t);
  }
  ~ScopedDeadline() { h_.set_deadline(previous_); }
  ScopedDeadline(const ScopedDeadline&) = delete;
  ScopedDeadline& operator=(const ScopedDeadline&) = delete;

 private:
  Heuristic& h_;
  Heuristic::Clock::time_point previous_;
};

}  // namespace clips::heuristics
