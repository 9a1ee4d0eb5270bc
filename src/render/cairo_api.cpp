#include <cairo.h>

#include <memory>

#include "util/shared_library.hpp"

// The table's own file sees the real names (it does not include the
// redirecting macros of cairo_api.hpp's tail).
#define CLIPS_CAIRO_API_TABLE_ONLY
#include "render/cairo_api.hpp"

namespace clips::render {

const CairoApi& cairo_api() {
  struct Loaded {
    util::SharedLibrary lib{{"libcairo.so.2"}, "pictures need cairo (Debian: apt-get install libcairo2)"};
    CairoApi api{
#define CLIPS_CAIRO_LOOKUP(name) lib.function<decltype(&::name)>(#name),
        CLIPS_CAIRO_FUNCTIONS(CLIPS_CAIRO_LOOKUP)
#undef CLIPS_CAIRO_LOOKUP
    };
  };
  static const Loaded loaded;  // a failed load leaves it unset: the next call tries again
  return loaded.api;
}

}  // namespace clips::render
