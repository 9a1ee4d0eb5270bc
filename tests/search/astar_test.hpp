#pragma once
// The includes, helpers and fixtures of the search tests in astar_test.cpp, shared by
// the files of that name in tests/search/ and its label folders
// (docs/testing.md, "Labels").
// A*, uniform-cost search and RTAA*: optimality against exhaustive search,
// heuristic properties, budgets and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "data/dataset.hpp"
#include "domains/pack.hpp"
#include "heuristics/basic.hpp"
#include "search/rtaa.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

using namespace clips;

namespace astar_test {

std::shared_ptr<model::Specification> spec_for(const data::Dataset& ds, const std::string& problem, int gem, int costs) {
  return std::make_shared<model::Specification>(ds.task(problem), "(has human gem" + std::to_string(gem) + ")",
                                                fixtures::dkg_profile(costs));
}

// Exact cost-to-go by Dijkstra backwards is awkward with conditional
// successors, so use forward uniform-cost search from the state itself.
double true_cost(const model::Specification& spec, const pddl::State& s, size_t budget = 1u << 20) {
  heuristics::BlindHeuristic blind;
  search::SearchOptions o;
  o.max_nodes = budget;
  auto r = search::plan(spec, blind, s, o);
  if (r.status == search::SearchStatus::Success) return r.cost;
  if (r.status == search::SearchStatus::Failure) return model::kInf;
  return std::nan("");
}



// h_max that counts its estimate() calls and declares whether its estimates
// may depend on the root of prepare().
struct CountingHMax : heuristics::HMaxHeuristic {
  bool root_dependent = false;
  size_t calls = 0;
  double estimate(const uint64_t* s) override {
    ++calls;
    return heuristics::HMaxHeuristic::estimate(s);
  }
  using heuristics::HMaxHeuristic::estimate;
  bool estimates_depend_on_root() const override { return root_dependent; }
};



// The spec's REFINE / UPDATE (clips-spec.md 5.3) written directly on the
// generic A*, with its own value table and tree: the reference the
// Policy's specialised lookahead (cached successors, entry ids) must match.
struct ReferenceRefine {
  std::shared_ptr<const model::Specification> spec;
  std::shared_ptr<heuristics::Heuristic> h;
  std::map<std::vector<uint64_t>, double> v;
  std::set<std::vector<uint64_t>> tree;

  std::vector<uint64_t> key(const uint64_t* s) const { return {s, s + spec->task().num_words()}; }
  double value(const uint64_t* s) const {
    auto it = v.find(key(s));
    return it != v.end() ? it->second : -h->estimate(s);
  }

  void refine(const pddl::State& s, const search::SearchOptions& opts_in) {
    const pddl::Task& task = spec->task();
    h->prepare(*spec, s);
    struct Learned : heuristics::Heuristic {
      ReferenceRefine* r;
      explicit Learned(ReferenceRefine* rr) : r(rr) {}
      std::string name() const override { return "reference-learned"; }
      bool admissible() const override { return false; }
      bool consistent() const override { return false; }
      void prepare(const model::Specification&, const pddl::State&) override {}
      double estimate(const uint64_t* x) override { return -r->value(x); }
      bool prunes() const override { return r->h->prunes(); }
      bool keep(pddl::ActionId a) const override { return r->h->keep(a); }
    } learned(this);
    search::SearchOptions opts = opts_in;
    opts.extra_goal = [this](const uint64_t* x) { return tree.count(key(x)) != 0; };
    double best = -model::kInf;
    for (pddl::ActionId a : task.applicable_actions(s)) {
      const pddl::State c = task.apply(s, a);
      auto known = v.find(c.words);
      if (known != v.end() && known->second == -model::kInf) continue;
      if (spec->is_goal(c)) {
        v[c.words] = 0;
      } else {
        const search::SearchResult r = search::astar(*spec, learned, c, opts);
        const search::StateRegistry& reg = *r.registry;
        if (r.status == search::SearchStatus::Failure) {
          for (int id = 0; id < reg.size(); ++id) v[key(reg.get(id))] = -model::kInf;
        } else {
          const auto& t = r.nodes[r.terminal];
          const double f_t = t.g + t.h;
          v[key(reg.get(r.terminal))] = -t.h;
          for (int id = 0; id < reg.size(); ++id)
            if (!r.nodes[id].open && id != r.terminal) v[key(reg.get(id))] = -(f_t - r.nodes[id].g);
          if (r.status == search::SearchStatus::Success)
            for (int id = r.terminal; r.nodes[id].parent >= 0; id = r.nodes[id].parent)
              tree.insert(key(reg.get(r.nodes[id].parent)));
        }
      }
      best = std::max(best, -spec->cost(a) + value(c.data()));
    }
    v[s.words] = best;
  }
};

}  // namespace astar_test
using namespace astar_test;
