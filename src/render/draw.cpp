#include "render/draw.hpp"
#include "render/cairo_api.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include "render/theme.hpp"

namespace clips::render::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Glyphs are drawn in unit coordinates; outlines must stay visible (>= ~1 px)
// when a cell is only 16 px wide.
double unit_width(double s, double unit, double min_px) { return std::max(unit, min_px / s); }

struct UnitBox {
  cairo_t* cr;
  UnitBox(cairo_t* c, double x, double y, double s) : cr(c) {
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_scale(cr, s, s);
  }
  ~UnitBox() { cairo_restore(cr); }
};

bool is_light(Rgb c) { return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b > 160; }

}  // namespace

Canvas::Canvas(int width, int height)
    : surface_(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, std::max(width, 1),
                                          std::max(height, 1))),
      cr_(cairo_create(surface_)) {
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS ||
      cairo_status(cr_) != CAIRO_STATUS_SUCCESS) {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
    throw std::runtime_error("cairo: cannot create a " + std::to_string(width) + "x" +
                             std::to_string(height) + " surface");
  }
}

Canvas::~Canvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

Image Canvas::image() const {
  cairo_surface_flush(surface_);
  const int w = cairo_image_surface_get_width(surface_);
  const int h = cairo_image_surface_get_height(surface_);
  const int stride = cairo_image_surface_get_stride(surface_);
  const unsigned char* data = cairo_image_surface_get_data(surface_);
  Image img(w, h);
  std::uint8_t* out = img.rgba.data();
  for (int y = 0; y < h; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < w; ++x, out += 4) {
      const std::uint32_t v = row[x];  // premultiplied, native-endian ARGB
      const unsigned a = v >> 24;
      unsigned r = (v >> 16) & 0xFF, g = (v >> 8) & 0xFF, b = v & 0xFF;
      if (a != 0xFF && a != 0) {
        r = (r * 255 + a / 2) / a;
        g = (g * 255 + a / 2) / a;
        b = (b * 255 + a / 2) / a;
      }
      out[0] = static_cast<std::uint8_t>(r);
      out[1] = static_cast<std::uint8_t>(g);
      out[2] = static_cast<std::uint8_t>(b);
      out[3] = static_cast<std::uint8_t>(a);
    }
  }
  return img;
}

int base_font(const RenderOptions& o) {
  return o.font_px > 0 ? o.font_px
                       : std::clamp(static_cast<int>(std::lround(o.cell_px * 0.42)), 11, 18);
}

cairo_t* measure_context() {
  thread_local Canvas canvas(1, 1);
  return canvas.cr();
}

void set_rgb(cairo_t* cr, Rgb c, double alpha) {
  if (alpha >= 1.0)
    cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
  else
    cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

void fill_rect(cairo_t* cr, const Rect& r, Rgb c) {
  set_rgb(cr, c);
  cairo_rectangle(cr, r.x, r.y, r.w, r.h);
  cairo_fill(cr);
}

void rounded_rect(cairo_t* cr, double x, double y, double w, double h, double r) {
  r = std::min({r, w / 2, h / 2});
  cairo_new_sub_path(cr);
  cairo_arc(cr, x + w - r, y + r, r, -kPi / 2, 0);
  cairo_arc(cr, x + w - r, y + h - r, r, 0, kPi / 2);
  cairo_arc(cr, x + r, y + h - r, r, kPi / 2, kPi);
  cairo_arc(cr, x + r, y + r, r, kPi, 3 * kPi / 2);
  cairo_close_path(cr);
}

void set_font(cairo_t* cr, double px, bool bold, bool italic) {
  cairo_select_font_face(cr, "DejaVu Sans", italic ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, px);
}

double text_width(cairo_t* cr, std::string_view text) {
  std::string s(text);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, s.c_str(), &ext);
  return ext.x_advance;
}

namespace {
// Index after the UTF-8 character starting at i.
std::size_t next_char(const std::string& s, std::size_t i) {
  ++i;
  while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) ++i;
  return i;
}
}  // namespace

std::vector<std::string> wrap_text(cairo_t* cr, const std::string& text, double max_width) {
  std::vector<std::string> words;
  std::string word;
  for (char c : text) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      if (!word.empty()) words.push_back(std::move(word));
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(std::move(word));

  std::vector<std::string> lines;
  std::string line;
  for (auto& w : words) {
    const std::string candidate = line.empty() ? w : line + " " + w;
    if (text_width(cr, candidate) <= max_width || (line.empty() && w.size() <= 1)) {
      line = candidate;
      continue;
    }
    if (!line.empty()) lines.push_back(line);
    line.clear();
    // A single word wider than the line is broken by characters.
    std::string rest = w;
    while (text_width(cr, rest) > max_width) {
      std::size_t cut = next_char(rest, 0);
      for (std::size_t i = cut; i < rest.size(); i = next_char(rest, i)) {
        if (text_width(cr, rest.substr(0, next_char(rest, i))) > max_width) break;
        cut = next_char(rest, i);
      }
      lines.push_back(rest.substr(0, cut));
      rest = rest.substr(cut);
    }
    line = rest;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

void draw_text(cairo_t* cr, double x, double baseline, std::string_view text, Rgb c) {
  set_rgb(cr, c);
  cairo_move_to(cr, x, baseline);
  std::string s(text);
  cairo_show_text(cr, s.c_str());
}

std::string fit_text(cairo_t* cr, const std::string& text, double max_width) {
  if (text_width(cr, text) <= max_width) return text;
  std::string cut = text;
  while (!cut.empty()) {
    std::size_t last = cut.size() - 1;
    while (last > 0 && (static_cast<unsigned char>(cut[last]) & 0xC0) == 0x80) --last;
    cut.erase(last);
    if (text_width(cr, cut + "\u2026") <= max_width) break;
  }
  return cut + "\u2026";
}

// ---- glyphs ----------------------------------------------------------------

void draw_key(cairo_t* cr, double x, double y, double s, Rgb c) {
  UnitBox box(cr, x, y, s);
  cairo_translate(cr, 0.5, 0.5);
  cairo_rotate(cr, -kPi / 5);  // a slanted key reads as "key" better than a flat one
  cairo_translate(cr, -0.5, -0.5);
  auto bow = [&] {
    cairo_new_path(cr);
    cairo_arc(cr, 0.28, 0.5, 0.18, 0, 2 * kPi);
    cairo_new_sub_path(cr);
    cairo_arc(cr, 0.28, 0.5, 0.07, 0, 2 * kPi);
  };
  auto blade = [&] {
    cairo_new_path(cr);
    cairo_rectangle(cr, 0.42, 0.44, 0.46, 0.12);
    cairo_rectangle(cr, 0.69, 0.52, 0.07, 0.15);
    cairo_rectangle(cr, 0.80, 0.52, 0.08, 0.19);
  };
  const double outline = unit_width(s, 0.07, 1.1);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  // Outline first as a thick dark stroke, then the fill on top: no seams
  // where the bow and the blade overlap.
  set_rgb(cr, shade(c, 0.55));
  cairo_set_line_width(cr, outline);
  bow();
  cairo_stroke(cr);
  blade();
  cairo_stroke(cr);
  set_rgb(cr, c);
  bow();
  cairo_fill(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  blade();
  cairo_fill(cr);
}

void draw_gem(cairo_t* cr, double x, double y, double s, Rgb c) {
  UnitBox box(cr, x, y, s);
  auto outline_path = [&] {
    cairo_new_path(cr);
    cairo_move_to(cr, 0.31, 0.20);
    cairo_line_to(cr, 0.69, 0.20);
    cairo_line_to(cr, 0.87, 0.41);
    cairo_line_to(cr, 0.50, 0.86);
    cairo_line_to(cr, 0.13, 0.41);
    cairo_close_path(cr);
  };
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  set_rgb(cr, shade(c, 0.55));
  cairo_set_line_width(cr, unit_width(s, 0.07, 1.1));
  outline_path();
  cairo_stroke(cr);
  set_rgb(cr, c);
  outline_path();
  cairo_fill(cr);
  if (s >= 20) {  // facets only where they can be seen
    set_rgb(cr, shade(c, 0.72));
    cairo_set_line_width(cr, unit_width(s, 0.025, 0.8));
    cairo_move_to(cr, 0.13, 0.41);
    cairo_line_to(cr, 0.87, 0.41);
    cairo_move_to(cr, 0.31, 0.20);
    cairo_line_to(cr, 0.38, 0.41);
    cairo_line_to(cr, 0.50, 0.86);
    cairo_line_to(cr, 0.62, 0.41);
    cairo_line_to(cr, 0.69, 0.20);
    cairo_stroke(cr);
  }
  set_rgb(cr, {255, 255, 255}, 0.55);
  cairo_move_to(cr, 0.33, 0.23);
  cairo_line_to(cr, 0.47, 0.23);
  cairo_line_to(cr, 0.36, 0.38);
  cairo_line_to(cr, 0.20, 0.38);
  cairo_close_path(cr);
  cairo_fill(cr);
}

void draw_door(cairo_t* cr, double x, double y, double s, Rgb c, bool locked) {
  UnitBox box(cr, x, y, s);
  const double edge = unit_width(s, 0.06, 1.5);
  if (!locked) {
    // Open door: a tinted floor framed by the door colour.
    set_rgb(cr, tint(c, 0.78));
    rounded_rect(cr, 0.05, 0.05, 0.90, 0.90, 0.10);
    cairo_fill(cr);
    set_rgb(cr, c);
    cairo_set_line_width(cr, unit_width(s, 0.09, 2.0));
    rounded_rect(cr, 0.08, 0.08, 0.84, 0.84, 0.08);
    cairo_stroke(cr);
    return;
  }
  set_rgb(cr, c);
  const double in = edge / 2 + 0.5 / s;  // keep the border inside the cell
  rounded_rect(cr, in, in, 1 - 2 * in, 1 - 2 * in, 0.10);
  cairo_fill_preserve(cr);
  set_rgb(cr, shade(c, 0.6));
  cairo_set_line_width(cr, edge);
  cairo_stroke(cr);
  // Padlock in a colour that contrasts with the door.
  const Rgb lock = is_light(c) ? Rgb{45, 45, 55} : Rgb{255, 255, 255};
  set_rgb(cr, lock);
  cairo_set_line_width(cr, unit_width(s, 0.075, 1.5));
  cairo_new_path(cr);
  cairo_arc(cr, 0.5, 0.46, 0.12, kPi, 2 * kPi);
  cairo_line_to(cr, 0.62, 0.52);
  cairo_move_to(cr, 0.38, 0.52);
  cairo_line_to(cr, 0.38, 0.46);
  cairo_stroke(cr);
  rounded_rect(cr, 0.30, 0.50, 0.40, 0.30, 0.05);
  cairo_fill(cr);
  if (s >= 20) {
    set_rgb(cr, c);
    cairo_arc(cr, 0.5, 0.62, 0.045, 0, 2 * kPi);
    cairo_fill(cr);
    cairo_rectangle(cr, 0.485, 0.63, 0.03, 0.09);
    cairo_fill(cr);
  }
}

void draw_human(cairo_t* cr, double x, double y, double s) {
  UnitBox box(cr, x, y, s);
  auto shape = [&] {
    cairo_new_path(cr);
    cairo_arc(cr, 0.5, 0.31, 0.15, 0, 2 * kPi);
    cairo_new_sub_path(cr);
    cairo_arc(cr, 0.5, 0.86, 0.31, kPi, 2 * kPi);
    cairo_close_path(cr);
  };
  set_rgb(cr, shade(theme::human, 0.55));
  cairo_set_line_width(cr, unit_width(s, 0.06, 1.4));
  shape();
  cairo_stroke(cr);
  set_rgb(cr, theme::human);
  shape();
  cairo_fill(cr);
}

void draw_robot(cairo_t* cr, double x, double y, double s) {
  UnitBox box(cr, x, y, s);
  const Rgb dark = shade(theme::robot, 0.55);
  set_rgb(cr, dark);
  cairo_set_line_width(cr, unit_width(s, 0.05, 1.2));
  cairo_move_to(cr, 0.5, 0.08);
  cairo_line_to(cr, 0.5, 0.2);
  cairo_stroke(cr);
  cairo_arc(cr, 0.5, 0.08, 0.055, 0, 2 * kPi);
  cairo_fill(cr);
  auto shape = [&] {
    cairo_new_path(cr);
    rounded_rect(cr, 0.27, 0.18, 0.46, 0.31, 0.07);
    rounded_rect(cr, 0.19, 0.54, 0.62, 0.34, 0.07);
  };
  cairo_set_line_width(cr, unit_width(s, 0.06, 1.4));
  shape();
  cairo_stroke(cr);
  set_rgb(cr, theme::robot);
  shape();
  cairo_fill(cr);
  set_rgb(cr, theme::robot_eye);
  cairo_arc(cr, 0.40, 0.33, 0.06, 0, 2 * kPi);
  cairo_fill(cr);
  cairo_arc(cr, 0.60, 0.33, 0.06, 0, 2 * kPi);
  cairo_fill(cr);
}

void draw_agent(cairo_t* cr, ObjectKind kind, double x, double y, double s) {
  if (kind == ObjectKind::Robot)
    draw_robot(cr, x, y, s);
  else
    draw_human(cr, x, y, s);
}

void draw_active_ring(cairo_t* cr, double x, double y, double s) {
  UnitBox box(cr, x, y, s);
  const double w = unit_width(s, 0.085, 2.0);
  set_rgb(cr, theme::marker);
  cairo_set_line_width(cr, w);
  cairo_arc(cr, 0.5, 0.5, 0.5 - w / 2, 0, 2 * kPi);
  cairo_stroke(cr);
}

// ---- chart -----------------------------------------------------------------

ChartGeometry chart_geometry(const std::vector<PosteriorBar>& bars, const RenderOptions& o,
                             int font) {
  const int bar_px = o.bar_px, min_rows = o.min_bar_rows;
  cairo_t* cr = measure_context();
  ChartGeometry g;
  g.gap = std::max(4, font / 2);
  g.header = static_cast<int>(std::lround(font * 1.8));
  g.row = static_cast<int>(std::lround(font * 1.6));
  g.bar_h = static_cast<int>(std::lround(g.row * 0.62));
  g.bar_max = bar_px > 0 ? bar_px : std::clamp(font * 9, 100, 200);
  set_font(cr, font);
  double label_w = 0;
  for (const auto& b : bars) label_w = std::max(label_w, text_width(cr, b.label));
  set_font(cr, font, true);
  for (const auto& b : bars) label_w = std::max(label_w, text_width(cr, b.label));
  g.label_w = std::max(static_cast<int>(std::ceil(label_w)), o.min_chart_label_px);
  const int value_w = static_cast<int>(std::ceil(text_width(cr, "100%")));
  const int rows = std::max(static_cast<int>(bars.size()), min_rows);
  set_font(cr, font, true);
  const int header_w = static_cast<int>(std::ceil(text_width(cr, "Goal posterior")));
  g.width = std::max(g.label_w + g.gap + g.bar_max + g.gap + value_w, header_w);
  g.height = g.header + rows * g.row;
  return g;
}

std::vector<Rect> bar_rects(const std::vector<PosteriorBar>& bars, const ChartGeometry& g, int x,
                            int y) {
  std::vector<Rect> out;
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const double p = std::clamp(std::isfinite(bars[i].probability) ? bars[i].probability : 0.0, 0.0, 1.0);
    out.push_back({x + g.label_w + g.gap, y + g.header + static_cast<int>(i) * g.row + (g.row - g.bar_h) / 2,
                   static_cast<int>(std::lround(p * g.bar_max)), g.bar_h});
  }
  return out;
}

void draw_chart(cairo_t* cr, const std::vector<PosteriorBar>& bars, const ChartGeometry& g,
                const Rect& where, int font) {
  if (bars.empty()) return;
  set_font(cr, font, true);
  draw_text(cr, where.x, where.y + font * 1.15, "Goal posterior", theme::text);
  std::size_t best = 0;
  for (std::size_t i = 1; i < bars.size(); ++i)
    if (bars[i].probability > bars[best].probability) best = i;
  const auto rects = bar_rects(bars, g, where.x, where.y);
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const Rect& r = rects[i];
    const double baseline = r.y + r.h / 2.0 + font * 0.36;
    set_font(cr, font, i == best);
    const double lw = text_width(cr, bars[i].label);
    draw_text(cr, where.x + g.label_w - lw, baseline, bars[i].label, theme::text);
    fill_rect(cr, {r.x, r.y, g.bar_max, r.h}, theme::track);
    if (r.w > 0) fill_rect(cr, r, named_colour(bars[i].colour));
    char pct[16];
    std::snprintf(pct, sizeof pct, "%.0f%%", std::clamp(bars[i].probability, 0.0, 1.0) * 100.0);
    set_font(cr, font, i == best);
    draw_text(cr, r.x + g.bar_max + g.gap, baseline, pct, i == best ? theme::text : theme::muted);
  }
}

// ---- caption ---------------------------------------------------------------

namespace {
int caption_pad(int font) { return std::max(4, static_cast<int>(std::lround(font * 0.6))); }
std::string quoted(const std::string& s) { return "\u201C" + s + "\u201D"; }
}  // namespace

int caption_line_height(int font) { return static_cast<int>(std::lround(font * 1.35)); }

int caption_height(int lines, int font) {
  return lines <= 0 ? 0 : lines * caption_line_height(font) + 2 * caption_pad(font);
}

std::vector<std::string> caption_lines(const std::string& caption, int width, int font) {
  if (caption.empty()) return {};
  cairo_t* cr = measure_context();
  set_font(cr, font, false, true);
  return wrap_text(cr, quoted(caption), width - 2 * caption_pad(font));
}

void draw_caption(cairo_t* cr, const std::string& caption, const Rect& where, int font) {
  if (caption.empty() || where.h <= 0) return;
  const int pad = caption_pad(font);
  set_rgb(cr, theme::panel);
  rounded_rect(cr, where.x + 0.5, where.y + 0.5, where.w - 1, where.h - 1, pad);
  cairo_fill_preserve(cr);
  set_rgb(cr, theme::panel_edge);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  set_font(cr, font, false, true);
  const auto lines = wrap_text(cr, quoted(caption), where.w - 2 * pad);
  const int lh = caption_line_height(font);
  const int max_lines = (where.h - 2 * pad) / lh;
  for (int i = 0; i < static_cast<int>(lines.size()) && i < max_lines; ++i)
    draw_text(cr, where.x + pad, where.y + pad + i * lh + font * 1.0, lines[i], theme::text);
}

}  // namespace clips::render::detail
