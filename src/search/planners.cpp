#include "search/planners.hpp"

namespace clips::search {

util::Choices<Planner>& planner_choices() {
  static util::Choices<Planner> table(
      "planner",
      {{Planner::AStar, "astar", "A*: one search to the goal, optimal with an admissible heuristic and --weight 1",
        {}},
       {Planner::Rtaa, "rtaa",
        "RTAA*: real-time search, a bounded lookahead before each executed action; see --max-steps, --time-limit",
        {}}});
  return table;
}

}  // namespace clips::search
