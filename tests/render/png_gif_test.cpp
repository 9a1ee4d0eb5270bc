#include <gif_lib.h>
#include <gtest/gtest.h>

#include <cstring>

#include "render/gif.hpp"
#include "render/render.hpp"
#include "render/theme.hpp"
#include "support.hpp"

namespace clips::render {
namespace {

using namespace testing;

Image gradient(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = &img.rgba[(static_cast<std::size_t>(y) * w + x) * 4];
      p[0] = static_cast<std::uint8_t>(x * 7), p[1] = static_cast<std::uint8_t>(y * 5);
      p[2] = static_cast<std::uint8_t>(x ^ y), p[3] = 255;
    }
  return img;
}

TEST(Png, RoundTripIsExact) {
  const Image img = gradient(37, 23);
  const auto path = out_dir() / "roundtrip.png";
  write_png(img, path);
  const Image back = read_png(path);
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 23);
  EXPECT_EQ(back.rgba, img.rgba);
}

TEST(Png, ErrorsAreExceptions) {
  EXPECT_THROW(write_png(Image{}, out_dir() / "empty.png"), std::invalid_argument);
  EXPECT_THROW(read_png(out_dir() / "does-not-exist.png"), std::runtime_error);
  const auto bogus = out_dir() / "bogus.png";
  { std::ofstream(bogus) << "not a png at all"; }
  EXPECT_THROW(read_png(bogus), std::runtime_error);
}

TEST(Gif, PaletteHas256ColoursIncludingTheTheme) {
  const auto pal = gif_palette();
  ASSERT_EQ(pal.size(), 256u);
  for (const Rgb c : theme_colours()) EXPECT_NE(std::find(pal.begin(), pal.end(), c), pal.end());
}

// Frames of a small run: the human walks right, the caption appears midway.
std::vector<GridScene> walk(int steps) {
  std::vector<GridScene> out;
  for (int t = 0; t < steps; ++t) {
    GridScene s(6, 3);
    s.set_wall(1, 1);
    s.objects = {{"key1", ObjectKind::Key, "red", 6, 3},
                 {"human", ObjectKind::Human, "", 1 + t % 6, 2},
                 {"robot", ObjectKind::Robot, "", 6, 1}};
    s.active_agent = t % 2 ? "robot" : "human";
    if (t >= steps / 2) s.caption = "Can you get the red key?";
    out.push_back(s);
  }
  return out;
}

struct SlurpedGif {
  GifFileType* gif = nullptr;
  explicit SlurpedGif(const std::filesystem::path& p) {
    int err = 0;
    gif = DGifOpenFileName(p.c_str(), &err);
    if (gif && DGifSlurp(gif) != GIF_OK) {
      DGifCloseFile(gif, &err);
      gif = nullptr;
    }
  }
  ~SlurpedGif() {
    int err = 0;
    if (gif) DGifCloseFile(gif, &err);
  }
  // Frame i composited over the previous ones (all frames use "do not dispose").
  Image frame(int i) const {
    Image canvas(gif->SWidth, gif->SHeight);
    const ColorMapObject* map = gif->SColorMap;
    for (int k = 0; k <= i; ++k) {
      const SavedImage& si = gif->SavedImages[k];
      const GifImageDesc& d = si.ImageDesc;
      for (int y = 0; y < d.Height; ++y)
        for (int x = 0; x < d.Width; ++x) {
          const GifColorType c = map->Colors[si.RasterBits[y * d.Width + x]];
          std::uint8_t* p = &canvas.rgba[((static_cast<std::size_t>(d.Top) + y) * canvas.width + d.Left + x) * 4];
          p[0] = c.Red, p[1] = c.Green, p[2] = c.Blue, p[3] = 255;
        }
    }
    return canvas;
  }
};

TEST(Gif, WritesAllFramesLoopingAndExactFlatColours) {
  const auto frames = render_frames(walk(7));
  const auto path = out_dir() / "walk.gif";
  write_gif(path, frames, 40);
  SlurpedGif g(path);
  ASSERT_NE(g.gif, nullptr);
  EXPECT_EQ(g.gif->ImageCount, 7);
  EXPECT_EQ(g.gif->SWidth, frames[0].width);
  EXPECT_EQ(g.gif->SHeight, frames[0].height);

  bool loops = false;
  for (int k = 0; k < g.gif->SavedImages[0].ExtensionBlockCount; ++k) {
    const ExtensionBlock& e = g.gif->SavedImages[0].ExtensionBlocks[k];
    if (e.Function == APPLICATION_EXT_FUNC_CODE && e.ByteCount == 11 &&
        std::memcmp(e.Bytes, "NETSCAPE2.0", 11) == 0)
      loops = true;
  }
  EXPECT_TRUE(loops);
  GraphicsControlBlock gcb;
  ASSERT_EQ(DGifSavedExtensionToGCB(g.gif, 3, &gcb), GIF_OK);
  EXPECT_EQ(gcb.DelayTime, 40);

  // After compositing, every frame matches its source up to quantisation, and
  // exactly wherever the source has a theme colour.
  const auto theme = theme_colours();
  for (int i : {0, 3, 6}) {
    const Image back = g.frame(i);
    long exact_expected = 0, exact_got = 0, far = 0;
    for (int y = 0; y < back.height; ++y)
      for (int x = 0; x < back.width; ++x) {
        const Rgb want = frames[i].at(x, y), got = back.at(x, y);
        if (std::find(theme.begin(), theme.end(), want) != theme.end()) {
          ++exact_expected;
          exact_got += want == got;
        }
        far += !near(want, got, 40);
      }
    EXPECT_EQ(exact_got, exact_expected) << "frame " << i;
    EXPECT_LT(far, back.width * back.height / 500) << "frame " << i;
  }
}

TEST(Gif, SizeMismatchIsReported) {
  std::vector<Image> frames{gradient(10, 10), gradient(10, 10), gradient(12, 10)};
  try {
    write_gif(out_dir() / "bad.gif", frames, 10);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("frame 3 is 12x10 but frame 1 is 10x10"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(write_gif(out_dir() / "none.gif", {}, 10), std::invalid_argument);

  GifWriter w(out_dir() / "writer.gif", 10, 10);
  w.add_frame(gradient(10, 10));
  EXPECT_THROW(w.add_frame(gradient(10, 11)), std::invalid_argument);
  w.add_frame(gradient(10, 10), 5);
  EXPECT_EQ(w.frame_count(), 2);
  w.close();
  SlurpedGif g(out_dir() / "writer.gif");
  ASSERT_NE(g.gif, nullptr);
  EXPECT_EQ(g.gif->ImageCount, 2);
}

TEST(Gif, IdenticalFramesStillCount) {
  const Image f = gradient(8, 8);
  const auto path = out_dir() / "same.gif";
  write_gif(path, {f, f, f}, 10);
  SlurpedGif g(path);
  ASSERT_NE(g.gif, nullptr);
  EXPECT_EQ(g.gif->ImageCount, 3);
}

}  // namespace
}  // namespace clips::render
