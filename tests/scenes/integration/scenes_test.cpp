#include "scenes/scenes_test.hpp"

namespace clips::scenes {
namespace scenes_test {
TEST(RenderCli, PngAndBadArguments) {
  testing::TempDir tmp("render");
  auto out = tmp.path / "f.png";
  auto r = testing::run(clips_binary() + " render --dataset " + examples_dkg() + " --plan e1.1.keys --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  auto img = render::read_png(out);
  EXPECT_GT(img.width, 200);
  EXPECT_GT(img.height, 100);
  r = testing::run(clips_binary() + " render --dataset " + examples_dkg() + " --plan e1.1.keys --step 999 --force --out " +
                   out.string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("out of range"), std::string::npos) << r.out;
  r = testing::run(clips_binary() + " render --dataset " + examples_dkg() +
                   " --plan e1.1.keys --out /nonexistent-dir-xyz/f.png");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("cannot write"), std::string::npos) << r.out;
  r = testing::run(clips_binary() + " render --dataset " + examples_dkg() + " --plan e1.1.keys");
  EXPECT_NE(r.status, 0);
}

TEST(RenderCli, GifHasObservedAndAssistedFrames) {
  testing::TempDir tmp("render-gif");
  auto gif = tmp.path / "run.gif";
  auto r = testing::run(clips_binary() + " render --dataset " + examples_dkg() + " --plan e2.1.doors --gif " + gif.string());
  ASSERT_EQ(r.status, 0) << r.out;
  auto a = testing::run(clips_binary() + " assist --dataset " + examples_dkg() + " --plan e2.1.doors --json");
  ASSERT_EQ(a.status, 0) << a.out;
  auto j = nlohmann::json::parse(a.out.substr(a.out.find('{')));
  const int assisted = static_cast<int>(j["plan"].size());
  auto ds = data::Dataset::load(examples_dkg());
  const int observed = static_cast<int>(ds.plan("e2.1.doors").observed.actions.size());
  int err = 0;
  GifFileType* g = DGifOpenFileName(gif.c_str(), &err);
  ASSERT_NE(g, nullptr) << GifErrorString(err);
  ASSERT_EQ(DGifSlurp(g), GIF_OK);
  EXPECT_EQ(g->ImageCount, observed + 1 + assisted);
  EXPECT_GT(g->SWidth, 200);
  DGifCloseFile(g, &err);
}

}  // namespace scenes_test

}  // namespace clips::scenes
