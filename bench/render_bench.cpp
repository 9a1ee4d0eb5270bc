// Rendering cost of one mDKG run: 50 frames at 32 px per cell on a 12x12
// grid, then the looping GIF (target: <= 1 s in total).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "render/gif.hpp"
#include "render/render.hpp"

namespace {

using namespace clips::render;

// A 12x12 map with a wall ring, inner walls, 3 keys, 3 doors, 4 gems; the
// human walks a loop, the robot fetches a key, the posterior drifts.
std::vector<GridScene> run_scenes(int steps) {
  std::vector<GridScene> out;
  const std::vector<std::pair<int, int>> loop = {{2, 2}, {3, 2}, {4, 2}, {5, 2}, {6, 2}, {7, 2}, {8, 2},
                                                 {9, 2}, {10, 2}, {10, 3}, {10, 4}, {10, 5}, {9, 5},
                                                 {8, 5}, {7, 5}, {6, 5}, {5, 5}, {4, 5}, {3, 5}, {2, 5},
                                                 {2, 4}, {2, 3}};
  for (int t = 0; t < steps; ++t) {
    GridScene s(12, 12);
    for (int i = 1; i <= 12; ++i) s.set_wall(i, 1), s.set_wall(i, 12), s.set_wall(1, i), s.set_wall(12, i);
    for (int x = 3; x <= 9; ++x) s.set_wall(x, 7);
    for (int y = 8; y <= 11; ++y) s.set_wall(6, y);
    s.objects = {{"key1", ObjectKind::Key, "red", 3, 3},     {"key2", ObjectKind::Key, "blue", 9, 4},
                 {"key3", ObjectKind::Key, "yellow", 4, 10}, {"door1", ObjectKind::Door, "red", 10, 7, "", true},
                 {"door2", ObjectKind::Door, "blue", 2, 7, "", t < 30},
                 {"door3", ObjectKind::Door, "yellow", 6, 8, "", true},
                 {"gem1", ObjectKind::Gem, "red", 3, 11},    {"gem2", ObjectKind::Gem, "yellow", 9, 11},
                 {"gem3", ObjectKind::Gem, "blue", 11, 2},   {"gem4", ObjectKind::Gem, "green", 11, 11}};
    const auto h = loop[t % loop.size()];
    s.objects.push_back({"human", ObjectKind::Human, "", h.first, h.second});
    s.objects.push_back({"robot", ObjectKind::Robot, "", 2 + (t / 2) % 9, 9});
    if (t > 10) s.objects[1].x = s.objects[1].y = -1, s.objects[1].held_by = "robot";
    s.active_agent = t % 2 ? "robot" : "human";
    if (t >= 8) s.caption = "Can you pass me the blue key? I think I need it for the door.";
    s.title = "Problem 1.1 - step " + std::to_string(t);
    const double a = 0.25 + 0.6 * t / steps;
    s.bars = {{"gem1", "red", 1 - a - 0.1}, {"gem2", "yellow", 0.05}, {"gem3", "blue", a}, {"gem4", "green", 0.05}};
    s.traces = {{"human", {loop.begin(), loop.begin() + 1 + t % loop.size()}}};
    out.push_back(std::move(s));
  }
  return out;
}

void BM_RenderRun50Gif(benchmark::State& state) {
  const auto scenes = run_scenes(50);
  RenderOptions opts;
  opts.cell_px = 32;
  const auto path = std::filesystem::temp_directory_path() / "clips_render_bench.gif";
  for (auto _ : state) {
    const auto frames = render_frames(scenes, opts);
    write_gif(path, frames, 30);
    benchmark::DoNotOptimize(frames.data());
  }
  std::filesystem::remove(path);
}
BENCHMARK(BM_RenderRun50Gif)->Unit(benchmark::kMillisecond);

// The same run when every frame is also saved as a PNG.
void BM_RenderRun50PngGif(benchmark::State& state) {
  const auto scenes = run_scenes(50);
  RenderOptions opts;
  opts.cell_px = 32;
  const auto dir = std::filesystem::temp_directory_path() / "clips_render_bench";
  std::filesystem::create_directories(dir);
  for (auto _ : state) {
    const auto frames = render_frames(scenes, opts);
    for (std::size_t i = 0; i < frames.size(); ++i)
      write_png(frames[i], dir / ("frame" + std::to_string(i) + ".png"));
    write_gif(dir / "run.gif", frames, 30);
  }
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_RenderRun50PngGif)->Unit(benchmark::kMillisecond);

}  // namespace
