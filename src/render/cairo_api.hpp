#pragma once
// cairo, opened when the first picture is drawn (util/shared_library.hpp):
// a call of the CLI that draws nothing does not load cairo and the dozen
// font and X libraries it brings. Include after <cairo.h>, in .cpp files
// only: each cairo_* call below goes through the table.
#include <cairo.h>

namespace clips::render {

#define CLIPS_CAIRO_FUNCTIONS(X) \
  X(cairo_arc) \
  X(cairo_close_path) \
  X(cairo_create) \
  X(cairo_destroy) \
  X(cairo_fill) \
  X(cairo_fill_preserve) \
  X(cairo_image_surface_create) \
  X(cairo_image_surface_get_data) \
  X(cairo_image_surface_get_height) \
  X(cairo_image_surface_get_stride) \
  X(cairo_image_surface_get_width) \
  X(cairo_line_to) \
  X(cairo_move_to) \
  X(cairo_new_path) \
  X(cairo_new_sub_path) \
  X(cairo_rectangle) \
  X(cairo_restore) \
  X(cairo_rotate) \
  X(cairo_save) \
  X(cairo_scale) \
  X(cairo_select_font_face) \
  X(cairo_set_fill_rule) \
  X(cairo_set_font_size) \
  X(cairo_set_line_cap) \
  X(cairo_set_line_join) \
  X(cairo_set_line_width) \
  X(cairo_set_source_rgb) \
  X(cairo_set_source_rgba) \
  X(cairo_show_text) \
  X(cairo_status) \
  X(cairo_stroke) \
  X(cairo_stroke_preserve) \
  X(cairo_surface_destroy) \
  X(cairo_surface_flush) \
  X(cairo_surface_status) \
  X(cairo_text_extents) \
  X(cairo_text_path) \
  X(cairo_translate)

struct CairoApi {
#define CLIPS_CAIRO_FIELD(name) decltype(&::name) name;
  CLIPS_CAIRO_FUNCTIONS(CLIPS_CAIRO_FIELD)
#undef CLIPS_CAIRO_FIELD
};

// Loads libcairo.so.2 on the first call; throws util::SharedLibraryError
// (naming the package to install) when it cannot.
const CairoApi& cairo_api();

}  // namespace clips::render

#ifndef CLIPS_CAIRO_API_TABLE_ONLY
#define cairo_arc(...) ::clips::render::cairo_api().cairo_arc(__VA_ARGS__)
#define cairo_close_path(...) ::clips::render::cairo_api().cairo_close_path(__VA_ARGS__)
#define cairo_create(...) ::clips::render::cairo_api().cairo_create(__VA_ARGS__)
#define cairo_destroy(...) ::clips::render::cairo_api().cairo_destroy(__VA_ARGS__)
#define cairo_fill(...) ::clips::render::cairo_api().cairo_fill(__VA_ARGS__)
#define cairo_fill_preserve(...) ::clips::render::cairo_api().cairo_fill_preserve(__VA_ARGS__)
#define cairo_image_surface_create(...) ::clips::render::cairo_api().cairo_image_surface_create(__VA_ARGS__)
#define cairo_image_surface_get_data(...) ::clips::render::cairo_api().cairo_image_surface_get_data(__VA_ARGS__)
#define cairo_image_surface_get_height(...) ::clips::render::cairo_api().cairo_image_surface_get_height(__VA_ARGS__)
#define cairo_image_surface_get_stride(...) ::clips::render::cairo_api().cairo_image_surface_get_stride(__VA_ARGS__)
#define cairo_image_surface_get_width(...) ::clips::render::cairo_api().cairo_image_surface_get_width(__VA_ARGS__)
#define cairo_line_to(...) ::clips::render::cairo_api().cairo_line_to(__VA_ARGS__)
#define cairo_move_to(...) ::clips::render::cairo_api().cairo_move_to(__VA_ARGS__)
#define cairo_new_path(...) ::clips::render::cairo_api().cairo_new_path(__VA_ARGS__)
#define cairo_new_sub_path(...) ::clips::render::cairo_api().cairo_new_sub_path(__VA_ARGS__)
#define cairo_rectangle(...) ::clips::render::cairo_api().cairo_rectangle(__VA_ARGS__)
#define cairo_restore(...) ::clips::render::cairo_api().cairo_restore(__VA_ARGS__)
#define cairo_rotate(...) ::clips::render::cairo_api().cairo_rotate(__VA_ARGS__)
#define cairo_save(...) ::clips::render::cairo_api().cairo_save(__VA_ARGS__)
#define cairo_scale(...) ::clips::render::cairo_api().cairo_scale(__VA_ARGS__)
#define cairo_select_font_face(...) ::clips::render::cairo_api().cairo_select_font_face(__VA_ARGS__)
#define cairo_set_fill_rule(...) ::clips::render::cairo_api().cairo_set_fill_rule(__VA_ARGS__)
#define cairo_set_font_size(...) ::clips::render::cairo_api().cairo_set_font_size(__VA_ARGS__)
#define cairo_set_line_cap(...) ::clips::render::cairo_api().cairo_set_line_cap(__VA_ARGS__)
#define cairo_set_line_join(...) ::clips::render::cairo_api().cairo_set_line_join(__VA_ARGS__)
#define cairo_set_line_width(...) ::clips::render::cairo_api().cairo_set_line_width(__VA_ARGS__)
#define cairo_set_source_rgb(...) ::clips::render::cairo_api().cairo_set_source_rgb(__VA_ARGS__)
#define cairo_set_source_rgba(...) ::clips::render::cairo_api().cairo_set_source_rgba(__VA_ARGS__)
#define cairo_show_text(...) ::clips::render::cairo_api().cairo_show_text(__VA_ARGS__)
#define cairo_status(...) ::clips::render::cairo_api().cairo_status(__VA_ARGS__)
#define cairo_stroke(...) ::clips::render::cairo_api().cairo_stroke(__VA_ARGS__)
#define cairo_stroke_preserve(...) ::clips::render::cairo_api().cairo_stroke_preserve(__VA_ARGS__)
#define cairo_surface_destroy(...) ::clips::render::cairo_api().cairo_surface_destroy(__VA_ARGS__)
#define cairo_surface_flush(...) ::clips::render::cairo_api().cairo_surface_flush(__VA_ARGS__)
#define cairo_surface_status(...) ::clips::render::cairo_api().cairo_surface_status(__VA_ARGS__)
#define cairo_text_extents(...) ::clips::render::cairo_api().cairo_text_extents(__VA_ARGS__)
#define cairo_text_path(...) ::clips::render::cairo_api().cairo_text_path(__VA_ARGS__)
#define cairo_translate(...) ::clips::render::cairo_api().cairo_translate(__VA_ARGS__)
#endif
