#include "scenes/scenes.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>

#include "domains/dkg/dkg_world.hpp"
#include "domains/vh/vh_world.hpp"
#include "render/gif.hpp"
#include "render/theme.hpp"
#include "util/error.hpp"

namespace clips::scenes {

using pddl::ObjectId;

render::GridScene dkg_scene(const domains::dkg::DkgWorld& w, const pddl::State& s, const SceneExtras& extras) {
  render::GridScene scene(w.width(), w.height());
  for (int y = 1; y <= w.height(); ++y)
    for (int x = 1; x <= w.width(); ++x)
      if (w.wall(x, y)) scene.set_wall(x, y);
  auto add = [&](ObjectId o, render::ObjectKind kind) {
    render::GridObject g;
    g.name = w.name(o);
    g.kind = kind;
    g.colour = w.color(o);
    if (kind == render::ObjectKind::Key || kind == render::ObjectKind::Gem) {
      if (auto h = w.holder(s, o)) g.held_by = w.name(*h);
    }
    if (g.held_by.empty()) {
      auto c = w.pos(s, o);
      g.x = c.x;
      g.y = c.y;
    }
    if (kind == render::ObjectKind::Door) g.locked = w.locked(s, o);
    scene.objects.push_back(std::move(g));
  };
  for (ObjectId d : w.doors()) add(d, render::ObjectKind::Door);
  for (ObjectId k : w.keys()) add(k, render::ObjectKind::Key);
  for (ObjectId g : w.gems()) add(g, render::ObjectKind::Gem);
  add(w.human(), render::ObjectKind::Human);
  add(w.robot(), render::ObjectKind::Robot);
  scene.active_agent = w.name(w.active_agent(s));
  scene.caption = extras.caption;
  scene.title = extras.title;
  scene.bars = extras.bars;
  scene.traces = extras.traces;
  return scene;
}

std::map<std::string, render::Rgb> scene_colours(const domains::Pack& pack) {
  std::map<std::string, render::Rgb> out;
  for (const auto& [type, hex] : pack.spec().scene_colours) {
    // The pack reader checked the "#rrggbb" form.
    const unsigned long v = std::stoul(hex.substr(1), nullptr, 16);
    out[type] = {static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)};
  }
  return out;
}

render::HomeScene vh_scene(const domains::Pack& pack, const domains::vh::VhWorld& w, const pddl::State& s,
                           const SceneExtras& extras) {
  render::HomeScene scene;
  scene.type_colours = scene_colours(pack);
  for (ObjectId f : w.fixtures()) {
    render::HomeFixture fx;
    fx.name = w.name(f);
    auto here = w.items_at(s, f);
    // Piles: start at each item with nothing on it, follow (stacked top below) down.
    auto on = [&](ObjectId top, ObjectId below) { return w.stacked(s, top, below); };
    std::vector<bool> used(here.size(), false);
    for (size_t i = 0; i < here.size(); ++i) {
      bool covered = false;
      for (ObjectId j : here) covered |= j != here[i] && on(j, here[i]);
      if (covered) continue;
      std::vector<std::string> pile;
      for (size_t cur = i; cur < here.size() && !used[cur];) {
        used[cur] = true;
        pile.push_back(w.name(here[cur]));
        size_t next = here.size();
        for (size_t k = 0; k < here.size(); ++k)
          if (!used[k] && on(here[cur], here[k])) next = k;
        cur = next;
      }
      fx.piles.push_back(std::move(pile));
    }
    for (size_t i = 0; i < here.size(); ++i)  // anything left (a cycle would be a bug upstream)
      if (!used[i]) fx.piles.push_back({w.name(here[i])});
    scene.fixtures.push_back(std::move(fx));
  }
  for (ObjectId a : {w.actor(), w.helper()}) {
    render::HomeAgent ag;
    ag.name = w.name(a);
    ag.kind = a == w.actor() ? render::ObjectKind::Human : render::ObjectKind::Robot;
    for (ObjectId f : w.fixtures())
      if (w.next_to(s, a, f)) ag.at = w.name(f);
    for (ObjectId i : w.items())
      if (w.holding(s, a, i)) ag.held.push_back(w.name(i));
    scene.agents.push_back(std::move(ag));
    if (w.active(s, a)) scene.active_agent = w.name(a);
  }
  scene.caption = extras.caption;
  scene.title = extras.title;
  scene.bars = extras.bars;
  return scene;
}

std::string goal_colour(const pddl::Task& task, const domains::Pack& pack, const std::string& goal) {
  if (!task.find_object(goal)) return "";
  // The first qualifier value that names a colour the pictures know.
  for (const auto& q : pack.qualifier_of(task)(goal)) {
    if (q.args.size() != 2) continue;
    const std::string& value = q.args[0] == goal ? q.args[1] : q.args[0];
    const render::Rgb c = render::named_colour(value), none = render::theme::neutral;
    if (c.r != none.r || c.g != none.g || c.b != none.b) return value;
  }
  return "";
}

std::vector<render::PosteriorBar> posterior_bars(const pddl::Task& task, const domains::Pack& pack,
                                                 const std::vector<std::string>& goals,
                                                 const std::vector<double>& p) {
  std::vector<render::PosteriorBar> bars;
  for (size_t g = 0; g < goals.size(); ++g)
    bars.push_back({goals[g], goal_colour(task, pack, goals[g]), g < p.size() ? p[g] : 0.0});
  return bars;
}

namespace {

std::string caption_at(const data::PlanRecord& plan, int t) {
  std::string c;
  for (const auto& u : plan.observed.utterances)
    if (u.index <= t) c += (c.empty() ? "" : " ") + u.text;
  return c;
}

}  // namespace

PlanFrames plan_frames(const data::Dataset& ds, const data::PlanRecord& plan, const PlanRun& run) {
  auto task = ds.task(plan.problem_id);
  PlanFrames out;
  out.scene = ds.pack().spec().scene;
  if (out.scene == domains::SceneKind::Text)
    throw InputError("the " + ds.pack().name() + " pack draws no pictures (its scene is \"text\"; see docs/domains.md)");
  auto sim = pddl::simulate(*task, task->initial_state(), plan.observed);
  std::vector<pddl::State> states = sim.states;
  out.observed_steps = static_cast<int>(sim.actions.size());
  for (const auto& text : run.assisted) {
    auto a = task->find_action(text);
    if (!a) throw InputError("plan " + plan.id + ": unknown assisted action " + text);
    if (!task->applicable(*a, states.back().data()))
      throw InputError("plan " + plan.id + ": assisted action " + text + " is not applicable");
    states.push_back(task->apply(states.back(), *a));
  }
  out.assisted_steps = static_cast<int>(run.assisted.size());
  const int T = out.observed_steps;
  auto title = [&](int t) {
    if (t <= T) return plan.id + " \u00b7 observed step " + std::to_string(t) + "/" + std::to_string(T);
    return plan.id + " \u00b7 " + (run.label.empty() ? std::string("assisted") : run.label) + " step " +
           std::to_string(t - T) + "/" + std::to_string(out.assisted_steps);
  };
  auto bars_at = [&](int t) -> std::vector<render::PosteriorBar> {
    const std::vector<double>* p = nullptr;
    if (t <= T && t < static_cast<int>(run.observed_posterior.size())) p = &run.observed_posterior[t];
    else if (t > T && !run.final_posterior.empty()) p = &run.final_posterior;
    else if (!run.observed_posterior.empty()) p = &run.observed_posterior.back();
    if (!p || run.goals.empty()) return {};
    return posterior_bars(*task, ds.pack(), run.goals, *p);
  };
  if (out.scene == domains::SceneKind::Cards) {
    domains::vh::VhWorld world(*task);
    for (size_t t = 0; t < states.size(); ++t) {
      SceneExtras ex{caption_at(plan, static_cast<int>(t)), title(static_cast<int>(t)), bars_at(static_cast<int>(t)), {}};
      out.home.push_back(vh_scene(ds.pack(), world, states[t], ex));
    }
  } else {
    domains::dkg::DkgWorld world(*task);
    render::PlanTrace human{world.name(world.human()), {}}, robot{world.name(world.robot()), {}};
    for (size_t t = 0; t < states.size(); ++t) {
      for (auto* tr : {&human, &robot}) {
        auto c = world.pos(states[t], tr == &human ? world.human() : world.robot());
        if (c.on_grid() && (tr->cells.empty() || tr->cells.back() != std::make_pair(c.x, c.y)))
          tr->cells.push_back({c.x, c.y});
      }
      SceneExtras ex{caption_at(plan, static_cast<int>(t)), title(static_cast<int>(t)), bars_at(static_cast<int>(t)),
                     {human, robot}};
      out.grid.push_back(dkg_scene(world, states[t], ex));
    }
  }
  return out;
}

namespace {

// Frame sizes must agree across a GIF: reserve room like render_frames does.
std::vector<render::Image> render_all(const PlanFrames& f, const render::RenderOptions& opts) {
  return f.grid.empty() ? render::render_frames(f.home, opts) : render::render_frames(f.grid, opts);
}

void check_writable(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path p(path);
  fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError("cannot write " + path + ": directory " + dir.string() + " does not exist");
  if (fs::is_directory(p, ec)) throw InputError("cannot write " + path + ": it is a directory");
}

}  // namespace

render::Image render_plan_frame(const PlanFrames& f, size_t index, const render::RenderOptions& opts) {
  if (index >= f.size())
    throw InputError("step " + std::to_string(index) + " is out of range (0.." + std::to_string(f.size() - 1) + ")");
  return f.grid.empty() ? render::render_png(f.home[index], opts) : render::render_png(f.grid[index], opts);
}

void write_plan_png(const PlanFrames& f, size_t index, const std::string& path, const render::RenderOptions& opts) {
  auto img = render_plan_frame(f, index, opts);
  check_writable(path);
  try {
    render::write_png(img, path);
  } catch (const std::exception& e) {
    throw InputError("cannot write " + path + ": " + e.what());
  }
}

void write_plan_gif(const PlanFrames& f, const std::string& path, const render::RenderOptions& opts) {
  if (f.size() == 0) throw InputError("no frames to write to " + path);
  check_writable(path);
  auto frames = render_all(f, opts);
  // Linger on the start, on the utterance's first frame, at the end of the
  // observed prefix and on the last frame.
  auto caption = [&](size_t i) { return f.grid.empty() ? f.home[i].caption : f.grid[i].caption; };
  try {
    render::GifWriter gif(path, frames[0].width, frames[0].height, 40);
    for (size_t i = 0; i < frames.size(); ++i) {
      int delay = 40;
      if (i == 0 || i + 1 == frames.size()) delay = 150;
      else if (static_cast<int>(i) == f.observed_steps) delay = 120;
      else if (caption(i) != caption(i - 1)) delay = 150;
      gif.add_frame(frames[i], delay);
    }
    gif.close();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError("cannot write " + path + ": " + e.what());
  }
}

}  // namespace clips::scenes
