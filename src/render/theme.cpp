#include "render/theme.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <string>
#include <utility>

#include "util/hash.hpp"

namespace clips::render {
namespace {

struct Named {
  std::string_view name;
  Rgb rgb;
};
constexpr std::array<Named, 5> kNamed{{{"red", {214, 46, 46}},
                                      {"yellow", {242, 188, 22}},
                                      {"blue", {38, 102, 214}},
                                      {"green", {38, 158, 70}},
                                      {"pink", {236, 108, 178}}}};

const std::vector<Rgb> kPastels{{255, 196, 160}, {255, 226, 150}, {196, 230, 160}, {160, 220, 210},
                                 {168, 200, 245}, {206, 186, 240}, {245, 180, 210}, {230, 205, 170},
                                 {200, 210, 220}, {250, 170, 160}, {215, 225, 140}, {180, 180, 235}};
const std::vector<Rgb> kCardHeaders{{205, 160, 110}, {168, 206, 232}, {206, 196, 180}};

std::uint8_t clamp_byte(double v) {
  return static_cast<std::uint8_t>(std::clamp(v + 0.5, 0.0, 255.0));
}

}  // namespace

Rgb named_colour(std::string_view name) {
  std::string lower(name);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& n : kNamed)
    if (n.name == lower) return n.rgb;
  return theme::neutral;
}

Rgb shade(Rgb c, double f) {
  return {clamp_byte(c.r * f), clamp_byte(c.g * f), clamp_byte(c.b * f)};
}

Rgb tint(Rgb c, double a) {
  return {clamp_byte(c.r + (255 - c.r) * a), clamp_byte(c.g + (255 - c.g) * a),
          clamp_byte(c.b + (255 - c.b) * a)};
}

const std::vector<Rgb>& pastel_colours() { return kPastels; }
const std::vector<Rgb>& card_header_colours() { return kCardHeaders; }

Rgb hashed_pastel(std::string_view type) { return kPastels[util::fnv1a32(type) % kPastels.size()]; }

std::vector<Rgb> theme_colours() {
  using namespace theme;
  std::vector<Rgb> out{background, floor, gridline, wall, wall_edge, text, muted, human,
                       shade(human, 0.6), robot, shade(robot, 0.6), robot_eye, marker,
                       track, panel, panel_edge, neutral, shade(neutral, 0.6)};
  for (const auto& c : kCardHeaders) out.push_back(c);
  out.push_back(tint(marker, 0.8));
  for (const auto& n : kNamed) {
    out.push_back(n.rgb);
    out.push_back(shade(n.rgb, 0.6));
    out.push_back(tint(n.rgb, 0.78));  // open doors
  }
  for (const auto& p : kPastels) out.push_back(p);
  std::vector<Rgb> unique;
  for (const auto& c : out)
    if (std::find(unique.begin(), unique.end(), c) == unique.end()) unique.push_back(c);
  return unique;
}

}  // namespace clips::render
