#include "render/gif.hpp"

#include <gif_lib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "render/theme.hpp"

namespace clips::render {
namespace {

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

void add_unique(std::vector<Rgb>& pal, Rgb c) {
  if (pal.size() < 256 && std::find(pal.begin(), pal.end(), c) == pal.end()) pal.push_back(c);
}

std::vector<Rgb> build_palette() {
  // Flat areas use theme colours, so they map exactly; anti-aliased edges and
  // text fall back to greys, colour/floor mixes and the cube.
  std::vector<Rgb> pal = theme_colours();
  for (int i = 0; i < 16; ++i) {
    const auto v = static_cast<std::uint8_t>(i * 17);
    add_unique(pal, {v, v, v});
  }
  for (const char* name : {"red", "yellow", "blue", "green", "pink"}) {
    const Rgb c = named_colour(name);
    add_unique(pal, {static_cast<std::uint8_t>((c.r + theme::floor.r) / 2),
                     static_cast<std::uint8_t>((c.g + theme::floor.g) / 2),
                     static_cast<std::uint8_t>((c.b + theme::floor.b) / 2)});
  }
  // The largest uniform cube that still fits.
  const std::array<std::array<int, 3>, 5> cubes{{{6, 7, 6}, {6, 6, 6}, {6, 6, 5}, {5, 6, 5}, {5, 5, 5}}};
  for (const auto& [nr, ng, nb] : cubes) {
    if (pal.size() + static_cast<std::size_t>(nr * ng * nb) > 256) continue;
    for (int r = 0; r < nr; ++r)
      for (int g = 0; g < ng; ++g)
        for (int b = 0; b < nb; ++b)
          add_unique(pal, {static_cast<std::uint8_t>(r * 255 / (nr - 1)),
                           static_cast<std::uint8_t>(g * 255 / (ng - 1)),
                           static_cast<std::uint8_t>(b * 255 / (nb - 1))});
    break;
  }
  while (pal.size() < 256) pal.push_back(theme::background);  // GIF wants 2^n entries
  return pal;
}

// Nearest palette colour, cached on the top 6 bits of each channel. Palette
// colours seed the cache so flat areas always keep their exact colour.
class Quantizer {
 public:
  explicit Quantizer(const std::vector<Rgb>& pal) : pal_(pal), cache_(1 << 18, -1) {
    for (std::size_t i = pal_.size(); i-- > 0;) cache_[key(pal_[i])] = static_cast<std::int16_t>(i);
  }
  std::uint8_t index(Rgb c) {
    std::int16_t& slot = cache_[key(c)];
    if (slot < 0) slot = static_cast<std::int16_t>(nearest(c));
    return static_cast<std::uint8_t>(slot);
  }

 private:
  static std::size_t key(Rgb c) {
    return (static_cast<std::size_t>(c.r >> 2) << 12) | (static_cast<std::size_t>(c.g >> 2) << 6) | (c.b >> 2);
  }
  int nearest(Rgb c) const {
    int best = 0;
    long best_d = -1;
    for (std::size_t i = 0; i < pal_.size(); ++i) {
      const long dr = c.r - pal_[i].r, dg = c.g - pal_[i].g, db = c.b - pal_[i].b;
      const long d = 2 * dr * dr + 4 * dg * dg + 3 * db * db;  // rough perceptual weights
      if (best_d < 0 || d < best_d) {
        best_d = d;
        best = static_cast<int>(i);
      }
    }
    return best;
  }
  std::vector<Rgb> pal_;
  std::vector<std::int16_t> cache_;
};

[[noreturn]] void gif_fail(const std::string& what, int code) {
  const char* msg = GifErrorString(code);
  throw std::runtime_error("giflib: " + what + ": " + (msg ? msg : "unknown error"));
}

}  // namespace

std::vector<Rgb> gif_palette() {
  static const std::vector<Rgb> pal = build_palette();
  return pal;
}

struct GifWriter::Impl {
  GifFileType* gif = nullptr;
  std::filesystem::path path;
  int width = 0, height = 0, delay = 50, frames = 0;
  Quantizer quant{gif_palette()};
  std::vector<std::uint8_t> prev, cur;  // palette indices of the last frame and this one

  void check(int rc, const char* what) const {
    if (rc != GIF_OK) gif_fail(what + (" (" + path.string() + ")"), gif->Error);
  }
};

GifWriter::GifWriter(const std::filesystem::path& path, int width, int height, int delay_cs,
                     int loop_count)
    : impl_(std::make_unique<Impl>()) {
  if (width <= 0 || height <= 0 || width > 65535 || height > 65535)
    throw std::invalid_argument("GifWriter: bad size " + size_text(width, height));
  Impl& m = *impl_;
  m.path = path;
  m.width = width;
  m.height = height;
  m.delay = std::clamp(delay_cs, 0, 65535);
  int err = 0;
  m.gif = EGifOpenFileName(path.c_str(), false, &err);
  if (!m.gif) gif_fail("cannot create " + path.string(), err);

  const auto pal = gif_palette();
  std::array<GifColorType, 256> colours{};
  for (std::size_t i = 0; i < 256; ++i) colours[i] = {pal[i].r, pal[i].g, pal[i].b};
  ColorMapObject* map = GifMakeMapObject(256, colours.data());
  if (!map) throw std::bad_alloc();
  EGifSetGifVersion(m.gif, true);
  const int rc = EGifPutScreenDesc(m.gif, width, height, 8, 0, map);  // copies the map
  GifFreeMapObject(map);
  m.check(rc, "screen descriptor");

  // NETSCAPE2.0 application extension: loop the animation.
  const auto loops = static_cast<unsigned>(std::clamp(loop_count, 0, 65535));
  GifByteType app[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  GifByteType sub[] = {1, static_cast<GifByteType>(loops & 0xFF), static_cast<GifByteType>(loops >> 8)};
  m.check(EGifPutExtensionLeader(m.gif, APPLICATION_EXT_FUNC_CODE), "loop extension");
  m.check(EGifPutExtensionBlock(m.gif, sizeof app, app), "loop extension");
  m.check(EGifPutExtensionBlock(m.gif, sizeof sub, sub), "loop extension");
  m.check(EGifPutExtensionTrailer(m.gif), "loop extension");
}

GifWriter::~GifWriter() {
  try {
    close();
  } catch (...) {  // destructors must not throw; close() reports errors
  }
}

GifWriter::GifWriter(GifWriter&&) noexcept = default;
GifWriter& GifWriter::operator=(GifWriter&& other) noexcept {
  if (this != &other) {
    try {
      close();
    } catch (...) {
    }
    impl_ = std::move(other.impl_);
  }
  return *this;
}

int GifWriter::width() const { return impl_ ? impl_->width : 0; }
int GifWriter::height() const { return impl_ ? impl_->height : 0; }
int GifWriter::frame_count() const { return impl_ ? impl_->frames : 0; }

void GifWriter::add_frame(const Image& frame, int delay_cs) {
  if (!impl_ || !impl_->gif) throw std::logic_error("GifWriter: add_frame after close");
  Impl& m = *impl_;
  if (frame.width != m.width || frame.height != m.height)
    throw std::invalid_argument("GIF frame " + std::to_string(m.frames + 1) + " is " +
                                size_text(frame.width, frame.height) + " but the animation is " +
                                size_text(m.width, m.height) + "; all frames must have the same size");
  if (frame.rgba.size() != static_cast<std::size_t>(m.width) * m.height * 4)
    throw std::invalid_argument("GIF frame " + std::to_string(m.frames + 1) + ": pixel buffer size does not match its size");

  // Quantise; runs of equal pixels (most of a scene) skip the cache lookup.
  const std::size_t n = static_cast<std::size_t>(m.width) * m.height;
  m.cur.resize(n);
  const std::uint8_t* p = frame.rgba.data();
  Rgb last{p[0], p[1], p[2]};
  std::uint8_t last_idx = m.quant.index(last);
  for (std::size_t i = 0; i < n; ++i, p += 4) {
    const Rgb c{p[0], p[1], p[2]};
    if (!(c == last)) {
      last = c;
      last_idx = m.quant.index(c);
    }
    m.cur[i] = last_idx;
  }

  // Only the rectangle that changed since the previous frame is stored; the
  // rest stays on screen (disposal "do not dispose").
  int x0 = 0, y0 = 0, x1 = m.width - 1, y1 = m.height - 1;
  if (m.frames > 0) {
    x0 = m.width, y0 = m.height, x1 = -1, y1 = -1;
    for (int y = 0; y < m.height; ++y) {
      const std::uint8_t* a = &m.cur[static_cast<std::size_t>(y) * m.width];
      const std::uint8_t* b = &m.prev[static_cast<std::size_t>(y) * m.width];
      if (std::equal(a, a + m.width, b)) continue;
      int l = 0, r = m.width - 1;
      while (a[l] == b[l]) ++l;
      while (a[r] == b[r]) --r;
      x0 = std::min(x0, l), x1 = std::max(x1, r), y0 = std::min(y0, y), y1 = y;
    }
    if (x1 < 0) x0 = x1 = y0 = y1 = 0;  // identical frame: one pixel keeps the timing
  }

  GraphicsControlBlock gcb{};
  gcb.DisposalMode = DISPOSE_DO_NOT;
  gcb.UserInputFlag = false;
  gcb.DelayTime = delay_cs < 0 ? m.delay : std::clamp(delay_cs, 0, 65535);
  gcb.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType ext[4];
  const std::size_t len = EGifGCBToExtension(&gcb, ext);
  m.check(EGifPutExtension(m.gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(len), ext), "frame timing");
  const int w = x1 - x0 + 1, h = y1 - y0 + 1;
  m.check(EGifPutImageDesc(m.gif, x0, y0, w, h, false, nullptr), "image descriptor");
  for (int y = y0; y <= y1; ++y)
    m.check(EGifPutLine(m.gif, &m.cur[static_cast<std::size_t>(y) * m.width + x0], w), "pixels");
  std::swap(m.prev, m.cur);
  ++m.frames;
}

void GifWriter::close() {
  if (!impl_ || !impl_->gif) return;
  int err = 0;
  const int rc = EGifCloseFile(impl_->gif, &err);  // frees the handle even on error
  impl_->gif = nullptr;
  if (rc != GIF_OK) gif_fail("closing " + impl_->path.string(), err);
}

void write_gif(const std::filesystem::path& path, const std::vector<Image>& frames, int delay_cs) {
  if (frames.empty()) throw std::invalid_argument("write_gif: no frames");
  for (std::size_t i = 1; i < frames.size(); ++i)
    if (frames[i].width != frames[0].width || frames[i].height != frames[0].height)
      throw std::invalid_argument("write_gif: frame " + std::to_string(i + 1) + " is " +
                                  size_text(frames[i].width, frames[i].height) + " but frame 1 is " +
                                  size_text(frames[0].width, frames[0].height) +
                                  "; all frames must have the same size");
  GifWriter writer(path, frames[0].width, frames[0].height, delay_cs);
  for (const auto& f : frames) writer.add_frame(f);
  writer.close();
}

}  // namespace clips::render
