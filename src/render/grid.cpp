// Doors, Keys & Gems scenes: grid, objects, inventory strip, caption, chart.
#include <algorithm>
#include <cmath>
#include <map>

#include "render/draw.hpp"
#include "render/cairo_api.hpp"
#include "render/render.hpp"
#include "render/theme.hpp"

namespace clips::render {
namespace {

using namespace detail;

int lr(double v) { return static_cast<int>(std::lround(v)); }

std::vector<const GridObject*> agents_of(const GridScene& s) {
  std::vector<const GridObject*> out;
  for (const auto& o : s.objects)
    if (o.is_agent()) out.push_back(&o);
  return out;
}

void draw_item(cairo_t* cr, const GridObject& o, double x, double y, double size) {
  const Rgb c = named_colour(o.colour);
  if (o.kind == ObjectKind::Key) draw_key(cr, x, y, size, c);
  else if (o.kind == ObjectKind::Gem) draw_gem(cr, x, y, size, c);
  else if (o.kind == ObjectKind::Door) draw_door(cr, x, y, size, c, o.locked);
}

// Small text with a halo in the background colour, so it stays legible on
// top of glyphs and door fills.
void halo_text(cairo_t* cr, double x, double baseline, const std::string& text, Rgb fg, Rgb halo,
               double halo_w) {
  cairo_save(cr);
  cairo_move_to(cr, x, baseline);
  cairo_text_path(cr, text.c_str());
  set_rgb(cr, halo, 0.85);
  cairo_set_line_width(cr, halo_w);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke_preserve(cr);
  set_rgb(cr, fg);
  cairo_fill(cr);
  cairo_restore(cr);
}

void draw_traces(cairo_t* cr, const GridScene& s, const GridLayout& L) {
  cairo_save(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const auto& t : s.traces) {
    if (t.cells.size() < 2) continue;
    const GridObject* a = s.find(t.agent);
    const bool robot = a && a->kind == ObjectKind::Robot;
    const Rgb c = robot ? theme::robot : theme::human;
    // Offset the two agents' paths so a shared corridor shows both.
    const double off = (robot ? 0.09 : -0.09) * L.cell;
    auto centre = [&](std::pair<int, int> p) {
      const Rect r = L.cell_rect(p.first, p.second);
      return std::pair<double, double>{r.x + r.w / 2.0 + off, r.y + r.h / 2.0 + off};
    };
    set_rgb(cr, c, 0.45);
    cairo_set_line_width(cr, std::max(2.0, L.cell * 0.12));
    auto [x0, y0] = centre(t.cells.front());
    cairo_move_to(cr, x0, y0);
    for (const auto& p : t.cells) {
      auto [x, y] = centre(p);
      cairo_line_to(cr, x, y);
    }
    cairo_stroke(cr);
    auto [xe, ye] = centre(t.cells.back());
    cairo_arc(cr, xe, ye, std::max(2.5, L.cell * 0.12), 0, 6.2832);
    cairo_fill(cr);
  }
  cairo_restore(cr);
}

void draw_inventory(cairo_t* cr, const GridScene& s, const GridLayout& L) {
  const auto agents = agents_of(s);
  if (agents.empty()) return;
  const int row = L.inventory.h / static_cast<int>(agents.size());
  const double glyph = row * 0.86;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const GridObject& a = *agents[i];
    const double y = L.inventory.y + static_cast<int>(i) * row;
    const double gy = y + (row - glyph) / 2;
    double x = L.inventory.x;
    draw_agent(cr, a.kind, x, gy, glyph);
    if (a.name == s.active_agent) draw_active_ring(cr, x - 1, gy - 1, glyph + 2);
    x += glyph + L.font * 0.4;
    const double baseline = y + row / 2.0 + L.font * 0.36;
    set_font(cr, L.font, true);
    const std::string who = a.name + ":";
    draw_text(cr, x, baseline, who, theme::text);
    x += text_width(cr, who) + L.font * 0.5;
    set_font(cr, L.font);
    const double right = L.inventory.x + L.inventory.w;
    std::vector<const GridObject*> held;
    for (const auto& o : s.objects)
      if (o.held_by == a.name && !o.is_agent()) held.push_back(&o);
    const bool any = !held.empty();
    // Names when they fit, otherwise glyphs only, otherwise an ellipsis.
    double named_w = 0;
    for (const auto* o : held) named_w += glyph + 1 + text_width(cr, o->name) + L.font * 0.8;
    const bool names = x + named_w <= right;
    for (const auto* o : held) {
      const double need = names ? glyph + 1 + text_width(cr, o->name) + L.font * 0.8 : glyph;
      if (x + need > right) {
        draw_text(cr, x, baseline, "\u2026", theme::muted);
        break;
      }
      draw_item(cr, *o, x, gy, glyph);
      x += glyph + 1;
      if (names) {
        draw_text(cr, x, baseline, o->name, theme::text);
        x += text_width(cr, o->name) + L.font * 0.8;
      }
    }
    if (!any) draw_text(cr, x, baseline, "holds nothing", theme::muted);
  }
}

}  // namespace

GridLayout layout(const GridScene& s, const RenderOptions& o) {
  GridLayout L;
  L.cell = std::max(4, o.cell_px);
  L.font = base_font(o);
  L.show_labels = o.labels == RenderOptions::Labels::Always ||
                  (o.labels == RenderOptions::Labels::Auto && L.cell >= 28);
  const int margin = std::max(6, lr(L.font * 0.8));
  const int gap = margin;
  const int grid_w = std::max(0, s.width) * L.cell, grid_h = std::max(0, s.height) * L.cell;

  int y = margin;
  if (!s.title.empty() || o.reserve_title) {
    L.title = {margin, y, 0, lr(L.font * 1.15 * 1.4)};
    y += L.title.h + gap / 2;
  }
  L.grid = {margin, y, grid_w, grid_h};
  int content_w = grid_w, top_h = grid_h;
  if (!s.bars.empty() || o.reserve_chart || o.min_bar_rows > 0) {
    const ChartGeometry g = chart_geometry(s.bars, o, L.font);
    L.chart = {margin + grid_w + 2 * gap, y, g.width, g.height};
    L.bars = bar_rects(s.bars, g, L.chart.x, L.chart.y);
    L.bar_max = g.bar_max;
    content_w += 2 * gap + g.width;
    top_h = std::max(top_h, g.height);
  }
  const int inner_w = std::max(content_w, L.font * 16);
  L.width = 2 * margin + inner_w;
  L.title.w = inner_w;
  y += top_h + gap;

  const int n_agents = static_cast<int>(agents_of(s).size());
  if (n_agents > 0) {
    const int row = std::max(lr(L.font * 1.9), 18);
    L.inventory = {margin, y, inner_w, n_agents * row};
    y += L.inventory.h + gap;
  }
  L.caption_lines = std::max(static_cast<int>(caption_lines(s.caption, inner_w, L.font).size()),
                             o.min_caption_lines);
  L.caption = {margin, y, inner_w, caption_height(L.caption_lines, L.font)};
  y += L.caption.h > 0 ? L.caption.h + margin : 0;
  L.height = std::max(y, 2 * margin);
  return L;
}

Image render_png(const GridScene& s, const RenderOptions& o) {
  if (s.width <= 0 || s.height <= 0 ||
      s.walls.size() != static_cast<std::size_t>(s.width) * s.height)
    throw std::invalid_argument("GridScene: width/height must be positive and walls must hold width*height cells");
  const GridLayout L = layout(s, o);
  Canvas canvas(L.width, L.height);
  cairo_t* cr = canvas.cr();
  fill_rect(cr, {0, 0, L.width, L.height}, theme::background);

  if (!s.title.empty()) {
    set_font(cr, L.font * 1.15, true);
    draw_text(cr, L.title.x, L.title.y + L.font * 1.15,
              fit_text(cr, s.title, L.title.w), theme::text);
  }

  // Floor, grid lines, walls.
  fill_rect(cr, L.grid, theme::floor);
  if (L.cell >= 10) {
    set_rgb(cr, theme::gridline);
    cairo_set_line_width(cr, 1.0);
    for (int x = 1; x < s.width; ++x) {
      cairo_move_to(cr, L.grid.x + x * L.cell + 0.5, L.grid.y);
      cairo_line_to(cr, L.grid.x + x * L.cell + 0.5, L.grid.y + L.grid.h);
    }
    for (int y = 1; y < s.height; ++y) {
      cairo_move_to(cr, L.grid.x, L.grid.y + y * L.cell + 0.5);
      cairo_line_to(cr, L.grid.x + L.grid.w, L.grid.y + y * L.cell + 0.5);
    }
    cairo_stroke(cr);
  }
  for (int y = 1; y <= s.height; ++y)
    for (int x = 1; x <= s.width; ++x)
      if (s.wall(x, y)) fill_rect(cr, L.cell_rect(x, y), theme::wall);
  set_rgb(cr, theme::wall);
  cairo_set_line_width(cr, 2.0);
  cairo_rectangle(cr, L.grid.x - 1, L.grid.y - 1, L.grid.w + 2, L.grid.h + 2);
  cairo_stroke(cr);

  // Doors lie under everything else (agents stand in open doorways).
  for (const auto& ob : s.objects)
    if (ob.kind == ObjectKind::Door && s.in_grid(ob.x, ob.y)) {
      const Rect r = L.cell_rect(ob.x, ob.y);
      draw_item(cr, ob, r.x, r.y, r.w);
    }
  draw_traces(cr, s, L);

  // Group the rest per cell so shared cells can be laid out together.
  std::map<std::pair<int, int>, std::vector<const GridObject*>> items, agents;
  for (const auto& ob : s.objects) {
    if (!s.in_grid(ob.x, ob.y) || ob.kind == ObjectKind::Door) continue;
    (ob.is_agent() ? agents : items)[{ob.x, ob.y}].push_back(&ob);
  }
  const double c = L.cell;
  for (const auto& [cell, list] : items) {
    if (agents.count(cell)) continue;  // drawn small after the agents
    const Rect r = L.cell_rect(cell.first, cell.second);
    const int n = static_cast<int>(list.size());
    const int k = static_cast<int>(std::ceil(std::sqrt(n)));
    const double sz = c / k;
    for (int i = 0; i < n; ++i)
      draw_item(cr, *list[i], r.x + (i % k) * sz, r.y + (i / k) * sz, sz);
  }
  for (const auto& [cell, list] : agents) {
    const Rect r = L.cell_rect(cell.first, cell.second);
    const int n = static_cast<int>(list.size());
    const double sz = n == 1 ? c * 0.9 : c * std::max(0.4, 1.1 / n);
    for (int i = 0; i < n; ++i) {
      const GridObject& a = *list[i];
      const double ax = n == 1 ? r.x + c * 0.05 : r.x + i * (c - sz) / (n - 1);
      const double ay = n == 1 ? r.y + c * 0.05 : r.y + (c - sz) / 2;
      draw_agent(cr, a.kind, ax, ay, sz);
      if (a.name == s.active_agent) draw_active_ring(cr, ax, ay, sz);
    }
    // Items lying under the agents, small in the bottom-right corner.
    if (auto it = items.find(cell); it != items.end()) {
      const double isz = c * (n == 1 ? 0.46 : 0.4);
      for (std::size_t i = 0; i < it->second.size(); ++i)
        draw_item(cr, *it->second[i], r.x + c - isz * (i + 1), r.y + c - isz, isz);
    }
    // Carried items as badges in the top-right corner (the inventory strip
    // lists them too; badges only where they are big enough to read).
    if (n == 1 && L.cell >= 24) {
      const double bsz = c * 0.38;
      int k = 0;
      for (const auto& ob : s.objects)
        if (!ob.is_agent() && ob.held_by == list[0]->name && k < 3)
          draw_item(cr, ob, r.x + c - bsz * (++k) + 1, r.y - 1, bsz);
    }
  }

  if (L.show_labels) {
    const double fs = std::max(8.0, c * 0.19);
    set_font(cr, fs);
    for (const auto& ob : s.objects) {
      if (ob.is_agent() || !s.in_grid(ob.x, ob.y)) continue;
      if (agents.count({ob.x, ob.y})) continue;  // keep agents uncluttered
      const Rect r = L.cell_rect(ob.x, ob.y);
      const bool on_door = ob.kind == ObjectKind::Door && ob.locked;
      const Rgb bg = on_door ? named_colour(ob.colour) : theme::floor;
      const bool light_bg = 0.299 * bg.r + 0.587 * bg.g + 0.114 * bg.b > 160;
      halo_text(cr, r.x + fs * 0.3, r.y + fs * 1.0, ob.name,
                light_bg ? theme::text : Rgb{255, 255, 255}, bg, std::max(1.5, fs * 0.3));
    }
  }

  if (!L.bars.empty()) draw_chart(cr, s.bars, chart_geometry(s.bars, o, L.font), L.chart, L.font);
  draw_inventory(cr, s, L);
  draw_caption(cr, s.caption, L.caption, L.font);
  return canvas.image();
}

void write_png(const GridScene& scene, const std::filesystem::path& path, const RenderOptions& opts) {
  write_png(render_png(scene, opts), path);
}

std::vector<Image> render_frames(const std::vector<GridScene>& scenes, RenderOptions opts) {
  // Pass 1: chart and title room; pass 2: caption lines, which depend on the width.
  for (const auto& s : scenes) {
    opts.min_bar_rows = std::max(opts.min_bar_rows, static_cast<int>(s.bars.size()));
    opts.reserve_chart = opts.reserve_chart || !s.bars.empty();
    opts.reserve_title = opts.reserve_title || !s.title.empty();
    if (!s.bars.empty())
      opts.min_chart_label_px = std::max(
          opts.min_chart_label_px, detail::chart_geometry(s.bars, opts, base_font(opts)).label_w);
  }
  for (const auto& s : scenes)
    opts.min_caption_lines = std::max(opts.min_caption_lines, layout(s, opts).caption_lines);
  std::vector<Image> out;
  out.reserve(scenes.size());
  for (const auto& s : scenes) out.push_back(render_png(s, opts));
  return out;
}

}  // namespace clips::render
