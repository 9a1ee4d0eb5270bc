// Card scenes: one card per fixture with its piles of items, the
// agents standing at it, an agent panel, caption and posterior chart.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "render/draw.hpp"
#include "render/cairo_api.hpp"
#include "render/render.hpp"
#include "render/theme.hpp"

namespace clips::render {
namespace {

using namespace detail;

int lr(double v) { return static_cast<int>(std::lround(v)); }

std::string item_type(const std::string& item) {
  std::size_t end = item.size();
  while (end > 0 && std::isdigit(static_cast<unsigned char>(item[end - 1]))) --end;
  return item.substr(0, end);
}

Rgb fixture_colour(const HomeScene& s, const std::string& name) {
  const auto it = s.type_colours.find(item_type(name));
  return it == s.type_colours.end() ? theme::neutral : it->second;
}

Rgb item_fill(const HomeScene& s, const std::string& item) {
  const std::string t = item_type(item);
  const auto it = s.type_colours.find(t);
  return it == s.type_colours.end() ? hashed_pastel(t) : it->second;
}

struct Metrics {
  int font, margin, pad, header, agent_zone, pill, pill_gap, pile_gap, colw, col_gap, agent_row;
};

Metrics metrics(const HomeScene& s, const RenderOptions& o) {
  Metrics m{};
  m.font = base_font(o);
  m.margin = std::max(6, lr(m.font * 0.8));
  m.pad = std::max(4, lr(m.font * 0.5));
  m.header = lr(m.font * 1.9);
  m.agent_zone = lr(m.font * 2.8);
  m.pill = lr(m.font * 1.55);
  m.pill_gap = std::max(1, m.font / 8);
  m.pile_gap = lr(m.font * 0.6);
  m.col_gap = std::max(4, lr(m.font * 0.6));
  m.agent_row = std::max(lr(m.font * 2.0), 18);
  cairo_t* cr = measure_context();
  double w = m.font * 7.0;
  set_font(cr, m.font, true);
  for (const auto& f : s.fixtures) w = std::max(w, text_width(cr, f.name) + 2.0 * m.pad);
  set_font(cr, m.font);
  // Must match draw_pill's text room: pill = colw - 2.6 pad, text = pill - font.
  auto item_w = [&](const std::string& it) { return text_width(cr, it) + m.font + 3.0 * m.pad; };
  for (const auto& f : s.fixtures)
    for (const auto& pile : f.piles)
      for (const auto& it : pile) w = std::max(w, item_w(it));
  for (const auto& a : s.agents)  // held items may be put down anywhere
    for (const auto& it : a.held) w = std::max(w, item_w(it));
  m.colw = static_cast<int>(std::ceil(w));
  return m;
}

int items_height(const HomeFixture& f, const Metrics& m) {
  int h = 0;
  for (const auto& pile : f.piles) {
    if (pile.empty()) continue;
    if (h > 0) h += m.pile_gap;
    h += static_cast<int>(pile.size()) * (m.pill + m.pill_gap);
  }
  return h;
}

void draw_pill(cairo_t* cr, Rgb c, const std::string& item, double x, double y, double w, double h,
               int font) {
  set_rgb(cr, c);
  rounded_rect(cr, x + 0.5, y + 0.5, w - 1, h - 1, h * 0.3);
  cairo_fill_preserve(cr);
  set_rgb(cr, shade(c, 0.7));
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  set_font(cr, font);
  const std::string t = fit_text(cr, item, w - font);
  draw_text(cr, x + (w - text_width(cr, t)) / 2, y + h / 2 + font * 0.36, t, theme::text);
}

}  // namespace

HomeLayout layout(const HomeScene& s, const RenderOptions& o) {
  const Metrics m = metrics(s, o);
  HomeLayout L;
  L.font = m.font;
  int y = m.margin;
  if (!s.title.empty() || o.reserve_title) {
    L.title = {m.margin, y, 0, lr(m.font * 1.15 * 1.4)};
    y += L.title.h + m.margin / 2;
  }
  int body = 0;
  for (const auto& f : s.fixtures) body = std::max(body, items_height(f, m));
  const int card_h = std::max(m.header + m.agent_zone + body + m.pad, o.min_body_px);
  const int n = static_cast<int>(s.fixtures.size());
  const int row_w = n > 0 ? n * m.colw + (n - 1) * m.col_gap : 0;
  L.fixtures = {m.margin, y, row_w, card_h};
  for (int i = 0; i < n; ++i)
    L.fixture_boxes.push_back({m.margin + i * (m.colw + m.col_gap), y, m.colw, card_h});
  int content_w = row_w, top_h = card_h;
  if (!s.bars.empty() || o.reserve_chart || o.min_bar_rows > 0) {
    const ChartGeometry g = chart_geometry(s.bars, o, m.font);
    L.chart = {m.margin + row_w + 2 * m.margin, y, g.width, g.height};
    L.bars = bar_rects(s.bars, g, L.chart.x, L.chart.y);
    L.bar_max = g.bar_max;
    content_w += 2 * m.margin + g.width;
    top_h = std::max(top_h, g.height);
  }
  const int inner_w = std::max(content_w, m.font * 20);
  L.width = 2 * m.margin + inner_w;
  L.title.w = inner_w;
  y += top_h + m.margin;
  y += static_cast<int>(s.agents.size()) * m.agent_row + (s.agents.empty() ? 0 : m.margin);
  L.caption_lines = std::max(static_cast<int>(caption_lines(s.caption, inner_w, m.font).size()),
                             o.min_caption_lines);
  L.caption = {m.margin, y, inner_w, caption_height(L.caption_lines, m.font)};
  y += L.caption.h > 0 ? L.caption.h + m.margin : 0;
  L.height = std::max(y, 2 * m.margin);
  return L;
}

Image render_png(const HomeScene& s, const RenderOptions& o) {
  const Metrics m = metrics(s, o);
  const HomeLayout L = layout(s, o);
  Canvas canvas(L.width, L.height);
  cairo_t* cr = canvas.cr();
  fill_rect(cr, {0, 0, L.width, L.height}, theme::background);
  if (!s.title.empty()) {
    set_font(cr, m.font * 1.15, true);
    draw_text(cr, L.title.x, L.title.y + m.font * 1.15, fit_text(cr, s.title, L.title.w),
              theme::text);
  }

  for (std::size_t i = 0; i < s.fixtures.size(); ++i) {
    const HomeFixture& f = s.fixtures[i];
    const Rect& b = L.fixture_boxes[i];
    const Rgb head = fixture_colour(s, f.name);
    // Card body, then the coloured header with the fixture name.
    set_rgb(cr, theme::panel);
    rounded_rect(cr, b.x + 0.5, b.y + 0.5, b.w - 1, b.h - 1, m.pad);
    cairo_fill_preserve(cr);
    set_rgb(cr, theme::panel_edge);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
    set_rgb(cr, head);
    rounded_rect(cr, b.x + 0.5, b.y + 0.5, b.w - 1, m.header, m.pad);
    cairo_fill(cr);
    set_font(cr, m.font, true);
    const std::string name = fit_text(cr, f.name, b.w - 2 * m.pad);
    draw_text(cr, b.x + (b.w - text_width(cr, name)) / 2, b.y + m.header / 2.0 + m.font * 0.36,
              name, theme::text);

    // Agents standing at this fixture.
    const double gsz = m.agent_zone * 0.86;
    double ax = b.x + m.pad;
    const double ay = b.y + m.header + (m.agent_zone - gsz) / 2;
    for (const auto& a : s.agents) {
      if (a.at != f.name) continue;
      draw_agent(cr, a.kind, ax, ay, gsz);
      if (a.name == s.active_agent) draw_active_ring(cr, ax, ay, gsz);
      ax += gsz + m.pad;
    }

    // Piles, top first; a bar on the left groups the items of one pile.
    double y = b.y + m.header + m.agent_zone;
    const double px = b.x + m.pad * 1.6, pw = b.w - m.pad * 2.6;
    for (const auto& pile : f.piles) {
      if (pile.empty()) continue;
      const double top = y;
      for (const auto& it : pile) {
        draw_pill(cr, item_fill(s, it), it, px, y, pw, m.pill, m.font);
        y += m.pill + m.pill_gap;
      }
      if (pile.size() > 1) {
        set_rgb(cr, theme::muted);
        cairo_set_line_width(cr, 2.0);
        cairo_move_to(cr, b.x + m.pad * 0.8, top + 2);
        cairo_line_to(cr, b.x + m.pad * 0.8, y - m.pill_gap - 2);
        cairo_stroke(cr);
      }
      y += m.pile_gap;
    }
  }

  // Agent panel: where each agent is and what it holds.
  int y = L.fixtures.y + std::max(L.fixtures.h, L.chart.h) + m.margin;
  for (const auto& a : s.agents) {
    const double gsz = m.agent_row * 0.86;
    const double gy = y + (m.agent_row - gsz) / 2;
    double x = m.margin;
    draw_agent(cr, a.kind, x, gy, gsz);
    if (a.name == s.active_agent) draw_active_ring(cr, x - 1, gy - 1, gsz + 2);
    x += gsz + m.font * 0.4;
    const double baseline = y + m.agent_row / 2.0 + m.font * 0.36;
    set_font(cr, m.font, true);
    draw_text(cr, x, baseline, a.name, theme::text);
    x += text_width(cr, a.name);
    set_font(cr, m.font);
    const std::string where = " at " + (a.at.empty() ? std::string("?") : a.at) + ", ";
    draw_text(cr, x, baseline, where, theme::muted);
    x += text_width(cr, where);
    if (a.held.empty()) {
      draw_text(cr, x, baseline, "holds nothing", theme::muted);
    } else {
      draw_text(cr, x, baseline, "holds ", theme::muted);
      x += text_width(cr, "holds ");
      const double right = L.width - m.margin;
      for (const auto& it : a.held) {
        const double w = text_width(cr, it) + 2.0 * m.pad;
        if (x + w > right) {
          draw_text(cr, x, baseline, "\u2026", theme::muted);
          break;
        }
        draw_pill(cr, item_fill(s, it), it, x, y + (m.agent_row - m.pill) / 2.0, w, m.pill, m.font);
        x += w + m.pad;
      }
    }
    y += m.agent_row;
  }

  if (!L.bars.empty()) draw_chart(cr, s.bars, chart_geometry(s.bars, o, m.font), L.chart, m.font);
  draw_caption(cr, s.caption, L.caption, m.font);
  return canvas.image();
}

void write_png(const HomeScene& scene, const std::filesystem::path& path, const RenderOptions& opts) {
  write_png(render_png(scene, opts), path);
}

std::vector<Image> render_frames(const std::vector<HomeScene>& scenes, RenderOptions opts) {
  for (const auto& s : scenes) {
    opts.min_bar_rows = std::max(opts.min_bar_rows, static_cast<int>(s.bars.size()));
    opts.reserve_chart = opts.reserve_chart || !s.bars.empty();
    opts.reserve_title = opts.reserve_title || !s.title.empty();
    if (!s.bars.empty())
      opts.min_chart_label_px = std::max(
          opts.min_chart_label_px, chart_geometry(s.bars, opts, base_font(opts)).label_w);
    opts.min_body_px = std::max(opts.min_body_px, layout(s, opts).fixtures.h);
  }
  for (const auto& s : scenes)
    opts.min_caption_lines = std::max(opts.min_caption_lines, layout(s, opts).caption_lines);
  std::vector<Image> out;
  out.reserve(scenes.size());
  for (const auto& s : scenes) out.push_back(render_png(s, opts));
  return out;
}

}  // namespace clips::render
