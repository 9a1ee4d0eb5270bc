#include "domains/dkg/dkg_pack.hpp"

#include <algorithm>

#include "domains/dkg/dkg_generate.hpp"
#include "domains/dkg/dkg_goals.hpp"
#include "domains/dkg/dkg_heuristic.hpp"
#include "domains/dkg/dkg_strips.hpp"
#include "domains/dkg/dkg_world.hpp"
#include "domains/required_object.hpp"
#include "util/error.hpp"

namespace clips::domains::dkg {

namespace {

class DkgPack : public Pack {
 public:
  using Pack::Pack;

  // Every agent and door on the grid, every key and gem on it or held. The
  // search and inference treat an object elsewhere as unreachable (a gem with
  // no position would get probability 0 without a word), so the problem is
  // rejected instead.
  void check_problem(const pddl::Task& t, const std::string& path) const override {
    const SourceLoc loc{path, 0, 0};
    auto walls = t.fluent("walls", {});
    if (!walls.matrix) throw InputError(loc, "a Doors-Keys-Gems problem needs a (walls) bit-matrix");
    const long long W = walls.matrix->cols, H = walls.matrix->rows;
    const std::string grid = std::to_string(W) + "x" + std::to_string(H) + " grid";
    const pddl::State s0 = t.initial_state();
    const auto agents = t.objects_of_type("agent");
    for (const char* type : {"agent", "door", "item"})
      for (pddl::ObjectId o : t.objects_of_type(type)) {
        const std::string& name = t.object_name(o);
        const bool item = std::string(type) == "item";
        if (item && std::any_of(agents.begin(), agents.end(), [&](pddl::ObjectId a) {
              return t.test(s0, t.atom("has", {t.object_name(a), name}));
            }))
          continue;
        const long long x = t.value(s0, t.fluent("xloc", {name})), y = t.value(s0, t.fluent("yloc", {name}));
        const std::string held = item ? " (and no agent holds it)" : "";
        if (x < 1 || y < 1) throw InputError(loc, name + " has no position on the " + grid + held);
        if (x > W || y > H)
          throw InputError(loc, name + " is outside the " + grid + " at (" + std::to_string(x) + ", " +
                                    std::to_string(y) + ")" + held);
      }
  }

  // The paper's profiles C1..C4 are the pack's data (pack.json); "1".."4"
  // and "c1".."c4" name them too.
  model::CostProfile cost_profile(const std::string& which) const override {
    if (which == "unit" || which == "task") return Pack::cost_profile(which);
    std::string w = which;
    if (!w.empty() && (w[0] == 'C' || w[0] == 'c')) w = w.substr(1);
    if (w == "1" || w == "2" || w == "3" || w == "4") return Pack::cost_profile("C" + w);
    throw InputError("--costs must be 1..4 (C1..C4), 'unit' or 'task' for doors-keys-gems, got '" + which + "'");
  }

  const util::Choices<heuristics::HeuristicMaker>* own_heuristics() const override {
    static util::Choices<heuristics::HeuristicMaker> table(
        "heuristic",
        {{[](const pddl::Task&) { return std::make_unique<DkgDistanceHeuristic>(); }, "dkg-dist",
          "a simple admissible and consistent bound for (has agent item) goals", {}},
         {[](const pddl::Task&) { return std::make_unique<DkgMstHeuristic>(); }, "dkg-mst",
          "the reference's DoorsKeysMSTHeuristic with its action pruning (inference's)", {}},
         {[](const pddl::Task&) { return std::make_unique<DkgMstHeuristic>(nullptr, 5, ItemPruning::Reference); },
          "dkg-mst-reference", "dkg-mst with the reference code's item pruning", {}}});
    return &table;
  }
  std::string default_admissible_heuristic() const override { return "dkg-dist"; }

  // Keys to pick up or hand over (unless the robot is forbidden to hold
  // them), and doors to unlock with a key of their colour. Held or used keys
  // stay candidates: a command may name them.
  std::vector<commands::Term> literal_candidates(const pddl::Task& task, const pddl::State& s) const override {
    const auto& config = language();
    const DkgWorld world(task);
    const pddl::ObjectId robot = require_object(task, config.listener);
    const std::string& robot_name = task.object_name(robot);
    const std::string& human_name = task.object_name(require_object(task, config.speaker));
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

  QualifierOf qualifier_of(const pddl::Task& task) const override {
    auto world = std::make_shared<DkgWorld>(task);
    const std::string qualifier = language().qualifier;
    return [world, &task, qualifier](const std::string& object) -> std::vector<commands::Term> {
      auto o = task.find_object(object);
      if (!o || world->color(*o).empty()) return {};
      return {commands::Term{qualifier, {object, world->color(*o)}}};
    };
  }

  std::function<bool(const std::string&)> goal_unsatisfiable(const pddl::Task&) const override {
    return dkg_goal_unsatisfiable;
  }

  std::string describe_state(const pddl::Task& task, const pddl::State& s) const override {
    DkgWorld w(task);
    return w.ascii(s) + w.describe(s);
  }

  std::optional<StripsExport> export_strips(const pddl::Task& task, const pddl::State& start, const std::string& goal,
                                            const model::CostProfile& costs) const override {
    return dkg::export_strips(task, start, goal, costs);
  }

  // Random maps for `clips generate` (dkg_generate.hpp).
  std::optional<GeneratedProblem> generate_problem(const GenerateParams& params, util::Rng& rng) const override {
    return generate_dkg_problem(params, rng);
  }
  std::vector<std::string> generated_kinds() const override { return {"gem", "key", "door"}; }

  // The human's moves to the gem's cell through the walls (doors counted
  // open), and the pick-up.
  std::optional<int> min_principal_actions(const pddl::Task& task, const pddl::State& s,
                                           const std::string& goal) const override {
    const DkgWorld w(task);
    const auto gem = task.find_object(goal);
    if (!gem || std::find(w.gems().begin(), w.gems().end(), *gem) == w.gems().end()) return std::nullopt;
    // Only when the human alone may hold it (else the robot could carry it over).
    if (!task.domain().find_predicate("forbidden") ||
        !task.test(s, task.atom("forbidden", {task.object_name(w.robot()), goal})))
      return std::nullopt;
    const Cell from = w.pos(s, w.human()), to = w.pos(s, *gem);
    if (from.x < 1 || to.x < 1) return std::nullopt;  // held, or off the grid
    const int width = w.width(), height = w.height();
    std::vector<int> dist(static_cast<size_t>(width * height), -1);
    auto at = [&](int x, int y) -> int& { return dist[static_cast<size_t>((y - 1) * width + (x - 1))]; };
    std::vector<Cell> queue{from};
    at(from.x, from.y) = 0;
    for (size_t i = 0; i < queue.size(); ++i) {
      const Cell c = queue[i];
      if (c.x == to.x && c.y == to.y) return at(c.x, c.y) + 1;
      for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int x = c.x + dx, y = c.y + dy;
        if (w.wall(x, y) || at(x, y) >= 0) continue;
        at(x, y) = at(c.x, c.y) + 1;
        queue.push_back(Cell{x, y});
      }
    }
    return std::nullopt;  // walled off: reachability is checked elsewhere
  }

  std::string object_list(const pddl::Task& task) const override {
    DkgWorld w(task);
    std::string out;
    for (auto group : {&w.keys(), &w.doors(), &w.gems()})
      for (auto o : *group) out += (out.empty() ? "" : ", ") + w.name(o) + " (" + w.color(o) + ")";
    return out;
  }
};

}  // namespace

PackPtr make_dkg_pack(PackSpec spec) { return std::make_shared<const DkgPack>(std::move(spec)); }

std::string dkg_misfit(const pddl::Domain& domain) {
  static const DomainNeeds needs{
      {"agent", "human", "robot", "key", "door", "gem", "color", "physical"},
      {{"has", 2}, {"locked", 1}, {"active", 1}, {"pickedup-by", 2}, {"unlocked-by", 2}, {"iscolor", 2}},
      {{"walls", 0}, {"xloc", 1}, {"yloc", 1}}};
  return domain_misfit(domain, needs);
}

}  // namespace clips::domains::dkg
