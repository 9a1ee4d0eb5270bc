// Plain value types describing what to draw. They know nothing about PDDL:
// the caller (eval/app) converts engine states into these.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "render/image.hpp"

namespace clips::render {

enum class ObjectKind { Human, Robot, Key, Door, Gem };

// A bar of the goal-posterior chart. colour is a colour name (see named_colour).
struct PosteriorBar {
  std::string label{};
  std::string colour{};
  double probability = 0.0;
};

// ---- Doors, Keys & Gems ------------------------------------------------------

struct GridObject {
  std::string name{};    // "key1", "door2", "human", ...
  ObjectKind kind = ObjectKind::Key;
  std::string colour{};  // red, yellow, blue, green, pink, or empty
  int x = -1, y = -1;  // 1-based cell; anything outside the grid means off-grid
  std::string held_by{}; // holder's name when carried, else empty
  bool locked = false; // doors only

  bool is_agent() const { return kind == ObjectKind::Human || kind == ObjectKind::Robot; }
};

// Cells an agent visits, drawn as a path (e.g. a planned or executed trajectory).
struct PlanTrace {
  std::string agent{};                     // name of a human/robot object
  std::vector<std::pair<int, int>> cells;  // (x, y), 1-based
};

struct GridScene {
  int width = 0, height = 0;  // cells
  std::vector<bool> walls;    // row-major, index (y-1)*width + (x-1)
  std::vector<GridObject> objects;
  std::string active_agent{};
  std::string caption{};        // the utterance, may be empty
  std::string title{};          // optional
  std::vector<PlanTrace> traces;
  std::vector<PosteriorBar> bars;  // optional goal posterior

  GridScene() = default;
  GridScene(int w, int h) : width(w), height(h), walls(static_cast<std::size_t>(w) * h, false) {}

  bool in_grid(int x, int y) const { return x >= 1 && y >= 1 && x <= width && y <= height; }
  bool wall(int x, int y) const {
    return in_grid(x, y) && walls[static_cast<std::size_t>(y - 1) * width + (x - 1)];
  }
  void set_wall(int x, int y, bool on = true) {
    if (in_grid(x, y)) walls[static_cast<std::size_t>(y - 1) * width + (x - 1)] = on;
  }
  const GridObject* find(const std::string& name) const {
    for (const auto& o : objects)
      if (o.name == name) return &o;
    return nullptr;
  }
};

// ---- card scenes: fixtures with piles of items ----------------------------------

struct HomeFixture {
  std::string name{};  // "table1", "cabinet3", "fridge1"
  // Items placed here. Each inner list is one pile, top of the pile first; a
  // loose item is a pile of one.
  std::vector<std::vector<std::string>> piles;
};

struct HomeAgent {
  std::string name{};  // "actor", "helper"
  ObjectKind kind = ObjectKind::Human;  // Human or Robot
  std::string at{};    // fixture name
  std::vector<std::string> held{};
};

struct HomeScene {
  std::vector<HomeFixture> fixtures;  // drawn left to right in this order
  std::vector<HomeAgent> agents;
  std::string active_agent{};
  std::string caption{};
  std::string title{};
  std::vector<PosteriorBar> bars;  // labels like "set_table2"
  // Fills by type, the name without its trailing digits ("plate" for
  // "plate3"), from the domain's pack. A fixture of another type is grey, an
  // item of another type gets a pastel picked by a hash of its type.
  std::map<std::string, Rgb> type_colours;
};

// ---- Options -------------------------------------------------------------------

struct RenderOptions {
  enum class Labels { Auto, Always, Never };

  int cell_px = 32;            // grid cell size; for HomeScene it scales text and boxes
  int font_px = 0;             // 0: derived from cell_px
  int bar_px = 0;              // longest possible bar; 0: derived
  Labels labels = Labels::Auto;  // Auto hides object labels when cells are small
  // Animation frames must share one size, so the caller can reserve room for
  // things that appear in some frames only (render_frames does this itself).
  int min_caption_lines = 1;
  int min_bar_rows = 0;
  bool reserve_chart = false;
  bool reserve_title = false;
  int min_chart_label_px = 0;  // chart label column width
  int min_body_px = 0;         // HomeScene: height of the fixture cards
};

}  // namespace clips::render
