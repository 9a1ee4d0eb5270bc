// Internal cairo helpers shared by the grid and home renderers (not part of
// the public API; include render/render.hpp instead).
#pragma once

#include <cairo.h>

#include <string>
#include <string_view>
#include <vector>

#include "render/image.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

namespace clips::render::detail {

// An image surface plus its context, released together.
class Canvas {
 public:
  Canvas(int width, int height);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;
  cairo_t* cr() const { return cr_; }
  Image image() const;  // copies out as straight RGBA

 private:
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

// Text size used for captions, charts and panels.
int base_font(const RenderOptions& o);

// A 1x1 canvas for text measurement during layout.
cairo_t* measure_context();

void set_rgb(cairo_t* cr, Rgb c, double alpha = 1.0);
void fill_rect(cairo_t* cr, const Rect& r, Rgb c);
void rounded_rect(cairo_t* cr, double x, double y, double w, double h, double radius);

void set_font(cairo_t* cr, double px, bool bold = false, bool italic = false);
double text_width(cairo_t* cr, std::string_view text);
// Greedy word wrap; words longer than max_width are broken by characters.
std::vector<std::string> wrap_text(cairo_t* cr, const std::string& text, double max_width);
void draw_text(cairo_t* cr, double x, double baseline, std::string_view text, Rgb c);
// Shortens text with "..." so that it fits max_width.
std::string fit_text(cairo_t* cr, const std::string& text, double max_width);

// Glyphs, each drawn inside the square (x, y, size).
void draw_key(cairo_t* cr, double x, double y, double s, Rgb c);
void draw_gem(cairo_t* cr, double x, double y, double s, Rgb c);
void draw_door(cairo_t* cr, double x, double y, double s, Rgb c, bool locked);
void draw_human(cairo_t* cr, double x, double y, double s);
void draw_robot(cairo_t* cr, double x, double y, double s);
void draw_agent(cairo_t* cr, ObjectKind kind, double x, double y, double s);
void draw_active_ring(cairo_t* cr, double x, double y, double s);

// Posterior chart: sizes depend on the labels and the font only.
struct ChartGeometry {
  int width = 0, height = 0;
  int header = 0, row = 0, label_w = 0, bar_max = 0, bar_h = 0, gap = 0;
};
ChartGeometry chart_geometry(const std::vector<PosteriorBar>& bars, const RenderOptions& o,
                             int font);
// Filled bar rectangles for a chart whose top-left corner is (x, y).
std::vector<Rect> bar_rects(const std::vector<PosteriorBar>& bars, const ChartGeometry& g, int x,
                            int y);
void draw_chart(cairo_t* cr, const std::vector<PosteriorBar>& bars, const ChartGeometry& g,
                const Rect& where, int font);

// Caption box: wrapped lines of the utterance inside a speech panel.
int caption_line_height(int font);
int caption_height(int lines, int font);
std::vector<std::string> caption_lines(const std::string& caption, int width, int font);
void draw_caption(cairo_t* cr, const std::string& caption, const Rect& where, int font);

}  // namespace clips::render::detail
