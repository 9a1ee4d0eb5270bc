// RGBA raster image and PNG input/output.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace clips::render {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// Straight (non-premultiplied) RGBA, row-major, 4 bytes per pixel, top row first.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}

  // Colour of pixel (x, y), alpha ignored; x, y are 0-based.
  Rgb at(int x, int y) const {
    const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
    return {p[0], p[1], p[2]};
  }
  std::uint8_t alpha(int x, int y) const {
    return rgba[(static_cast<std::size_t>(y) * width + x) * 4 + 3];
  }
};

// Writes an 8-bit RGBA PNG. Uses fast zlib settings: frames are written often.
// Throws std::runtime_error on I/O failure.
void write_png(const Image& image, const std::filesystem::path& path);
// The same PNG as bytes (for a caller that keeps the picture in memory).
std::string encode_png(const Image& image);

// Reads any PNG libpng understands, converted to 8-bit RGBA.
Image read_png(const std::filesystem::path& path);

}  // namespace clips::render
