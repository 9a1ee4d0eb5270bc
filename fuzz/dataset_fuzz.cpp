// The dataset loader's list files. The first byte picks the file:
//   even: stimuli.json (Doors-Keys-Gems entries, checked against two plans),
//   odd:  a VirtualHome goal set (goals/sets/<P>.txt, labels one per line);
// the remaining bytes are its text.
#include <map>
#include <vector>

#include "data/dataset.hpp"
#include "fuzz/fuzz_target.hpp"

namespace {

std::vector<clips::data::PlanRecord> known_plans() {
  std::vector<clips::data::PlanRecord> plans(2);
  plans[0].id = "1.1.keys";
  plans[0].problem_id = "1";
  plans[0].tag = "keys";
  plans[0].observed.utterances.push_back({"Can you pass me the red key?", 3, {"<plan>", 4, 1}});
  plans[1].id = "2.1.doors";
  plans[1].problem_id = "2";
  plans[1].tag = "doors";  // no utterance: an entry naming one is an error
  return plans;
}

const std::map<std::string, std::string> kGoalDefs = {
    {"set_table1", "(and (on plate1 table1) (on fork1 table1))"},
    {"stew_chicken", "(inside chicken1 pot1)"},
    {"wash_plates", "(inside plate1 sink1)"},
};

}  // namespace

CLIPS_FUZZ_TARGET(dataset) {
  using namespace clips::data;
  if (size == 0) return 0;
  const std::string text = clips::fuzz::as_text(data + 1, size - 1);
  static const std::vector<PlanRecord> plans = known_plans();
  try {
    if (data[0] % 2 == 0) {
      for (const auto& [name, s] : parse_stimuli(text, "<stimuli.json>", plans)) {
        for (int o : s.best_options)
          if (o < 1 || o > s.option_count) __builtin_trap();
      }
    } else {
      for (const auto& label : parse_goal_set(text, "<goals/sets>", kGoalDefs))
        if (!kGoalDefs.count(label)) __builtin_trap();
    }
  } catch (const clips::InputError&) {
  }
  return 0;
}
