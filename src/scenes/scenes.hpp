#pragma once
// Engine states -> render scenes (render/scene.hpp), and the frame sequence of
// one plan: the observed prefix followed by an assisted continuation, with the
// goal posterior beside every frame.
#include <map>
#include <string>
#include <vector>

#include "data/dataset.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

// The paper domains' world views (domains/dkg/dkg_world.hpp,
// domains/vh/vh_world.hpp), declared only: a user of this header needs them
// only when it draws one of those scenes.
namespace clips::domains::dkg {
class DkgWorld;
}  // namespace clips::domains::dkg
namespace clips::domains::vh {
class VhWorld;
}  // namespace clips::domains::vh

namespace clips::scenes {

struct SceneExtras {
  std::string caption;  // the utterance(s) spoken so far
  std::string title;
  std::vector<render::PosteriorBar> bars;
  std::vector<render::PlanTrace> traces;
};

// mDKG: walls, agents, keys (on the grid or held), doors (locked or open),
// gems, the active agent.
render::GridScene dkg_scene(const domains::dkg::DkgWorld& world, const pddl::State& s, const SceneExtras& extras = {});
// Card scenes: fixtures with their piles, where each agent is and what it
// holds, filled with the pack's scene colours.
render::HomeScene vh_scene(const domains::Pack& pack, const domains::vh::VhWorld& world, const pddl::State& s,
                           const SceneExtras& extras = {});
// A pack's scene colours ("#rrggbb" by type) as render colours.
std::map<std::string, render::Rgb> scene_colours(const domains::Pack& pack);

// Bars for a goal posterior; goals named after an object whose qualifier is a
// colour (mDKG gems) get that colour.
std::vector<render::PosteriorBar> posterior_bars(const pddl::Task& task, const domains::Pack& pack,
                                                 const std::vector<std::string>& goals,
                                                 const std::vector<double>& probabilities);
// The colour name of a goal label ("red" for a red gem; "" when none).
std::string goal_colour(const pddl::Task& task, const domains::Pack& pack, const std::string& goal);

// Everything needed to draw one plan over time.
struct PlanRun {
  std::vector<std::string> goals;                     // candidate goal labels
  std::vector<std::vector<double>> observed_posterior;  // [t] for t = 0..T (may be empty)
  std::vector<double> final_posterior;                // shown during assistance (may be empty)
  std::vector<std::string> assisted;                  // actions after s_T (may be empty)
  std::string label;                                  // assistance label for titles, e.g. "CLIPS"
};

// One frame per state: s_0 .. s_T (observed), then one per assisted action.
struct PlanFrames {
  domains::SceneKind scene = domains::SceneKind::Grid;
  std::vector<render::GridScene> grid;  // grid scenes (mDKG)
  std::vector<render::HomeScene> home;  // card scenes
  int observed_steps = 0;               // T
  int assisted_steps = 0;               // A; frames = T + 1 + A
  size_t size() const { return grid.empty() ? home.size() : grid.size(); }
};

// The pack's scene kind picks the picture (grid or cards). Throws InputError
// when an assisted action does not apply, or for a pack with no pictures
// (scene "text").
PlanFrames plan_frames(const data::Dataset& ds, const data::PlanRecord& plan, const PlanRun& run);

// Renders frames [first, last] and writes a looping GIF (slower on the first
// frame, when the utterance appears and on the last frame).
void write_plan_gif(const PlanFrames& frames, const std::string& path, const render::RenderOptions& opts = {});
// Renders one frame as PNG.
void write_plan_png(const PlanFrames& frames, size_t index, const std::string& path,
                    const render::RenderOptions& opts = {});
render::Image render_plan_frame(const PlanFrames& frames, size_t index, const render::RenderOptions& opts = {});

}  // namespace clips::scenes
