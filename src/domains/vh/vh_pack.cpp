#include "domains/vh/vh_pack.hpp"

#include <algorithm>

#include "domains/vh/vh_value.hpp"
#include "domains/vh/vh_world.hpp"
#include "domains/required_object.hpp"
#include "util/error.hpp"

namespace clips::domains::vh {

namespace {

class VhPack : public Pack {
 public:
  using Pack::Pack;

  const util::Choices<heuristics::HeuristicMaker>* own_heuristics() const override {
    static util::Choices<heuristics::HeuristicMaker> table(
        "heuristic",
        {{[](const pddl::Task& task) { return std::make_unique<VhValueHeuristic>(task); }, "vh",
          "a lower bound counting goal items still to move and fixtures still to visit", {}},
         {[](const pddl::Task& task) { return std::make_unique<VhPlanningHeuristic>(task); }, "vh-planning",
          "vh with the literal listener's action filter", {}}});
    return &table;
  }
  std::string default_admissible_heuristic() const override { return "hmax"; }

  // Items the helper could grab where they lie now, fixtures and items by name.
  std::vector<commands::Term> literal_candidates(const pddl::Task& task, const pddl::State& s) const override {
    const VhWorld world(task);
    const std::string& helper = task.object_name(require_object(task, language().listener));
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

  QualifierOf qualifier_of(const pddl::Task& task) const override {
    auto world = std::make_shared<VhWorld>(task);
    const std::string qualifier = language().qualifier;
    return [world, &task, qualifier](const std::string& object) -> std::vector<commands::Term> {
      auto o = task.find_object(object);
      if (!o || !task.object_is_a(*o, "item")) return {};
      const std::string type = world->item_type(*o);
      if (type.empty()) return {};
      return {commands::Term{qualifier, {object, type}}};
    };
  }

  std::string describe_state(const pddl::Task& task, const pddl::State& s) const override {
    return VhWorld(task).describe(s);
  }

  std::string object_list(const pddl::Task& task) const override {
    VhWorld w(task);
    std::string out;
    for (auto i : w.items()) out += (out.empty() ? "" : ", ") + w.name(i) + " (" + w.item_type(i) + ")";
    for (auto f : w.fixtures()) out += (out.empty() ? "" : ", ") + w.name(f);
    return out;
  }
};

}  // namespace

PackPtr make_vh_pack(PackSpec spec) { return std::make_shared<const VhPack>(std::move(spec)); }

std::string vh_misfit(const pddl::Domain& domain) {
  static const DomainNeeds needs{{"agent", "fixture", "item", "itype"}, {{"itemtype", 2}}, {}};
  return domain_misfit(domain, needs);
}

}  // namespace clips::domains::vh
