// The goal-set files of a dataset whose pack takes its candidate goals from
// goal sets (the repo's kitchen dataset): goals/sets/<P>.txt (one goal label
// a line) and goals/definitions/<label>.pddl (the label's goal condition).
// One input is the set's text, then any number of definitions, each starting
// with a line "~~~ <label>":
//
//   pancakes
//   omelette
//   ~~~ pancakes
//   (made pancakes)
//   ~~~ omelette
//   (and (made omelette) (not (holding human pan1)))
//
// What the loader and its callers do with them is done here, against the
// kitchen's domain and problem 1 as its pack grounds them: the set is parsed
// against the definitions (data::parse_goal_set), each listed goal's
// condition compiled into a goal specification (as inference does) and
// checked in the initial state, the labels written as JSON (as `infer --json`
// and the server do), and the true and the reached goal picked by the pack's
// rules (as `validate` and the experiments do).
//
// Accepted: clips::InputError for a bad file. Anything else escaping (a
// JSON type error for a label that is not UTF-8, say) is a finding.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "data/dataset.hpp"
#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"
#include "fuzz/fuzz_target.hpp"
#include "model/spec.hpp"
#include "pddl/task.hpp"
#include "util/data_dir.hpp"

namespace {

constexpr size_t kMaxInputBytes = 8192;
constexpr size_t kMaxGoals = 16;
const std::string kMarker = "~~~ ";

struct Kitchen {
  clips::domains::PackPtr pack;
  std::shared_ptr<const clips::pddl::Task> task;
};

const Kitchen& kitchen() {
  static const Kitchen k = [] {
    const std::string dir = clips::util::data_path("datasets/kitchen");
    auto dp = clips::domains::load_domain_with_pack(dir + "/domain.pddl", dir);
    auto task = clips::data::ground_problem(*dp.pack, dp.domain, dir + "/problems/1.pddl");
    return Kitchen{dp.pack, task};
  }();
  return k;
}

// Splits the input into the set's text and label -> definition text (a
// label defined twice keeps its last text, as a folder cannot hold both).
void split(const std::string& text, std::string& set, std::map<std::string, std::string>& defs) {
  std::string* current = &set;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    if (line.compare(0, kMarker.size(), kMarker) == 0) {
      std::string& def = defs[line.substr(kMarker.size())];
      def.clear();
      current = &def;
    } else {
      *current += line;
      *current += '\n';
    }
    start = end + 1;
  }
}

}  // namespace

CLIPS_FUZZ_TARGET(goalset) {
  using namespace clips;
  if (size > kMaxInputBytes) return 0;
  const Kitchen& k = kitchen();
  std::string set_text;
  std::map<std::string, std::string> defs;
  split(fuzz::as_text(data, size), set_text, defs);
  try {
    const std::vector<std::string> labels = data::parse_goal_set(set_text, "goals/sets/1.txt", defs);
    if (labels.size() > kMaxGoals) return 0;
    std::vector<data::GoalSpec> goals;
    for (const auto& label : labels) {
      if (!defs.count(label)) __builtin_trap();  // parse_goal_set let an undefined label through
      goals.push_back({label, defs.at(label), "goals/definitions/" + label + ".pddl"});
    }
    nlohmann::json out = nlohmann::json::array();
    const pddl::State s0 = k.task->initial_state();
    for (const auto& g : goals) {
      model::Specification spec(k.task, g.condition, k.pack->default_profile(), g.source);
      // Labels reach JSON outputs; conditions do not (only their compiled form).
      out.push_back({{"goal", g.label}, {"holds", spec.is_goal(s0)}});
    }
    // Throws nlohmann's type_error (an internal error) for text that is not UTF-8.
    (void)out.dump();
    if (!goals.empty()) {
      const int truth = k.pack->true_goal_index(*k.task, goals, labels.front(), {}, {});
      if (truth != 0) __builtin_trap();  // the first label is the plan's tag here
      (void)domains::reached_goal_index(*k.task, goals, {}, {});
    }
  } catch (const InputError&) {
  }
  return 0;
}
