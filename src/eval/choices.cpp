#include "eval/choices.hpp"

#include "domains/pack.hpp"
#include "engine/choices.hpp"
#include "eval/methods.hpp"
#include "search/planners.hpp"

namespace clips::eval {

util::ChoiceCatalogue choice_catalogue() {
  util::ChoiceCatalogue c = engine::choice_catalogue();
  c.push_back({"assist", assist_policy_choices().info()});
  c.push_back({"bench_assist", assistance_set_choices().info()});
  c.push_back({"literal_method", domains::literal_method_choices().info()});
  c.push_back({"baseline", baseline_choices().info()});
  c.push_back({"planner", search::planner_choices().info()});
  return c;
}

std::string choices_markdown() {
  std::string md = "| choice | name | what it does |\n|---|---|---|\n";
  for (const auto& [id, kind] : choice_catalogue())
    for (const auto& c : kind.choices) {
      std::string also;
      for (const auto& a : c.aliases) also += (also.empty() ? " (also " : ", ") + std::string("`") + a + "`";
      if (!also.empty()) also += ")";
      md += "| `" + id + "` | `" + c.name + "`" + also + " | " + c.help + " |\n";
    }
  return md;
}

}  // namespace clips::eval
