// Cairo renderings of grid scenes and card scenes (fixtures with their items).
#pragma once

#include <filesystem>
#include <vector>

#include "render/image.hpp"
#include "render/scene.hpp"

namespace clips::render {

struct Rect {
  int x = 0, y = 0, w = 0, h = 0;
  bool contains(int px, int py) const { return px >= x && py >= y && px < x + w && py < y + h; }
};

// Where everything goes in a grid rendering. Exposed so tests and overlays
// can find cells, bars and the caption without guessing.
struct GridLayout {
  int width = 0, height = 0;  // image size
  int cell = 0;
  int font = 0;
  Rect title, grid, chart, inventory, caption;
  std::vector<Rect> bars;     // filled part of each posterior bar
  int bar_max = 0;            // length of a bar with probability 1
  int caption_lines = 0;      // lines reserved for the caption
  bool show_labels = false;

  Rect cell_rect(int x, int y) const {  // 1-based cell
    return {grid.x + (x - 1) * cell, grid.y + (y - 1) * cell, cell, cell};
  }
};

struct HomeLayout {
  int width = 0, height = 0;
  int font = 0;
  Rect title, fixtures, chart, caption;
  std::vector<Rect> fixture_boxes;  // one per scene fixture, same order
  std::vector<Rect> bars;
  int bar_max = 0;
  int caption_lines = 0;
};

GridLayout layout(const GridScene& scene, const RenderOptions& opts = {});
HomeLayout layout(const HomeScene& scene, const RenderOptions& opts = {});

Image render_png(const GridScene& scene, const RenderOptions& opts = {});
Image render_png(const HomeScene& scene, const RenderOptions& opts = {});

// Renders a sequence with one shared layout (caption lines, chart and title
// room reserved for the largest frame), so all images have the same size.
std::vector<Image> render_frames(const std::vector<GridScene>& scenes, RenderOptions opts = {});
std::vector<Image> render_frames(const std::vector<HomeScene>& scenes, RenderOptions opts = {});

void write_png(const GridScene& scene, const std::filesystem::path& path,
               const RenderOptions& opts = {});
void write_png(const HomeScene& scene, const std::filesystem::path& path,
               const RenderOptions& opts = {});

}  // namespace clips::render
