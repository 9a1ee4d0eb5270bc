// Looping animated GIFs from same-sized RGBA frames (giflib), with a fixed
// 256-colour palette: the theme's colours plus a uniform colour cube.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "render/image.hpp"

namespace clips::render {

class GifWriter {
 public:
  // delay_cs: default time per frame in 1/100 s; loop_count 0 = forever.
  GifWriter(const std::filesystem::path& path, int width, int height, int delay_cs = 50,
            int loop_count = 0);
  ~GifWriter();  // closes if still open; call close() to see errors
  GifWriter(GifWriter&&) noexcept;
  GifWriter& operator=(GifWriter&&) noexcept;

  // Throws std::invalid_argument if the frame's size differs from the GIF's.
  // delay_cs < 0 uses the default delay.
  void add_frame(const Image& frame, int delay_cs = -1);
  void close();

  int width() const;
  int height() const;
  int frame_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Checks all sizes before creating the file. Throws std::invalid_argument for
// no frames or frames of different sizes, std::runtime_error for I/O errors.
void write_gif(const std::filesystem::path& path, const std::vector<Image>& frames,
               int delay_cs = 50);

// The palette used for every GIF (exactly 256 entries).
std::vector<Rgb> gif_palette();

}  // namespace clips::render
