// Test helpers: ASCII mDKG maps -> GridScene, pixel counting, output paths.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "render/image.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

namespace clips::render::testing {

inline std::filesystem::path out_dir() {
  std::filesystem::path d = std::filesystem::path(CLIPS_BINARY_DIR) / "render-test-out";
  std::filesystem::create_directories(d);
  return d;
}

inline std::filesystem::path dataset_dir() {
  if (const char* env = std::getenv("CLIPS_DATASET")) return env;
  return std::filesystem::path(CLIPS_SOURCE_DIR) / ".." / "shared" / "dataset";
}

// Parses a map per spec 2.5 (rows top first; objects numbered in row-major order).
inline GridScene parse_ascii_map(const std::string& text) {
  std::vector<std::string> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos) continue;
    rows.push_back(line.substr(b, line.find_last_not_of(" \t\r") - b + 1));
  }
  int w = 0;
  for (const auto& r : rows) w = std::max(w, static_cast<int>(r.size()));
  GridScene s(w, static_cast<int>(rows.size()));
  auto colour_of = [](char c) -> std::string {
    switch (std::tolower(c)) {
      case 'r': return "red";
      case 'b': return "blue";
      case 'y': return "yellow";
      case 'e': return "green";
      case 'p': return "pink";
    }
    return "";
  };
  const char* gem_colours[] = {"red", "yellow", "blue", "green"};
  int keys = 0, doors = 0, gems = 0;
  GridObject human{"human", ObjectKind::Human}, robot{"robot", ObjectKind::Robot};
  for (int y = 1; y <= s.height; ++y)
    for (int x = 1; x <= static_cast<int>(rows[y - 1].size()); ++x) {
      const char c = rows[y - 1][x - 1];
      if (c == 'W') s.set_wall(x, y);
      else if (c == 'h') human.x = x, human.y = y;
      else if (c == 'm') robot.x = x, robot.y = y;
      else if (std::string("rbyep").find(c) != std::string::npos)
        s.objects.push_back({"key" + std::to_string(++keys), ObjectKind::Key, colour_of(c), x, y});
      else if (std::string("RBYEP").find(c) != std::string::npos)
        s.objects.push_back({"door" + std::to_string(++doors), ObjectKind::Door, colour_of(c), x, y, "", true});
      else if (c == 'g' || c == 'G') {
        ++gems;
        s.objects.push_back({"gem" + std::to_string(gems), ObjectKind::Gem,
                             gems <= 4 ? gem_colours[gems - 1] : "", x, y});
      }
    }
  s.objects.push_back(human);
  s.objects.push_back(robot);
  s.active_agent = "human";
  return s;
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

inline int count_pixels(const Image& img, const Rect& r, const std::function<bool(Rgb)>& pred) {
  int n = 0;
  for (int y = std::max(0, r.y); y < std::min(img.height, r.y + r.h); ++y)
    for (int x = std::max(0, r.x); x < std::min(img.width, r.x + r.w); ++x)
      if (pred(img.at(x, y))) ++n;
  return n;
}

inline int count_colour(const Image& img, const Rect& r, Rgb c) {
  return count_pixels(img, r, [c](Rgb p) { return p == c; });
}

inline bool near(Rgb a, Rgb b, int tol) {
  return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}

}  // namespace clips::render::testing
