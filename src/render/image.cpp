#include "render/image.hpp"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace clips::render {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File open_file(const std::filesystem::path& path, const char* mode) {
  File f(std::fopen(path.c_str(), mode));
  if (!f) throw std::runtime_error("cannot open " + path.string());
  return f;
}

// libpng reports errors by longjmp to the frame that called setjmp; we keep the
// message and throw from that frame, so no exception crosses libpng's C frames.
thread_local std::string png_error_message;
void png_keep_error(png_structp png, png_const_charp msg) {
  png_error_message = msg ? msg : "unknown error";
  png_longjmp(png, 1);
}
void png_quiet(png_structp, png_const_charp) {}

}  // namespace

namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t n) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), n);
}
void no_flush(png_structp) {}

}  // namespace

std::string encode_png(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    throw std::invalid_argument("encode_png: image has no pixels or a wrong buffer size");
  std::string bytes;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, png_keep_error, png_quiet);
  if (!png) throw std::runtime_error("png_create_write_struct failed");
  png_infop info = png_create_info_struct(png);
  struct Guard {
    png_structp* p; png_infop* i;
    ~Guard() { png_destroy_write_struct(p, i); }
  } guard{&png, &info};
  if (setjmp(png_jmpbuf(png))) throw std::runtime_error("libpng: " + png_error_message);
  png_set_write_fn(png, &bytes, append_bytes, no_flush);
  // Renderings are opaque: drop the alpha channel then (a quarter less data).
  bool opaque = true;
  for (std::size_t i = 3; i < image.rgba.size() && opaque; i += 4) opaque = image.rgba[i] == 0xFF;
  png_set_IHDR(png, info, image.width, image.height, 8,
               opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Flat-colour art: the "up" filter plus run-length zlib is several times
  // faster than the defaults and the files stay small.
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_compression_strategy(png, Z_RLE);
  png_set_compression_level(png, 1);
  png_write_info(png, info);
  if (opaque) png_set_filler(png, 0, PNG_FILLER_AFTER);  // libpng strips the 4th byte
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, &image.rgba[static_cast<std::size_t>(y) * image.width * 4]);
  png_write_end(png, nullptr);
  return bytes;
}

void write_png(const Image& image, const std::filesystem::path& path) {
  const std::string bytes = encode_png(image);
  File f = open_file(path, "wb");
  if (std::fwrite(bytes.data(), 1, bytes.size(), f.get()) != bytes.size() || std::fflush(f.get()) != 0)
    throw std::runtime_error("cannot write " + path.string());
}

Image read_png(const std::filesystem::path& path) {
  File f = open_file(path, "rb");
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, png_keep_error, png_quiet);
  if (!png) throw std::runtime_error("png_create_read_struct failed");
  png_infop info = png_create_info_struct(png);
  struct Guard {
    png_structp* p; png_infop* i;
    ~Guard() { png_destroy_read_struct(p, i, nullptr); }
  } guard{&png, &info};
  Image img;
  std::vector<png_bytep> rows;
  if (setjmp(png_jmpbuf(png)))
    throw std::runtime_error("libpng reading " + path.string() + ": " + png_error_message);
  png_init_io(png, f.get());
  png_read_info(png, info);
  // Normalise every PNG flavour to 8-bit RGBA.
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xFF, PNG_FILLER_AFTER);
  png_read_update_info(png, info);
  img = Image(static_cast<int>(png_get_image_width(png, info)),
              static_cast<int>(png_get_image_height(png, info)));
  rows.resize(img.height);
  for (int y = 0; y < img.height; ++y)
    rows[y] = &img.rgba[static_cast<std::size_t>(y) * img.width * 4];
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  return img;
}

}  // namespace clips::render
