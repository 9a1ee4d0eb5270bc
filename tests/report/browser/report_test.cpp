#include "report/report_test.hpp"

namespace clips::report {
namespace report_test {
TEST_F(BenchReportTest, RendersInHeadlessChromium) {
  ASSERT_EQ(result_->status, 0) << result_->out;
  const std::string chromium = "/usr/bin/chromium";
  if (!fs::exists(chromium)) GTEST_SKIP() << chromium << " not installed (Debian package chromium)";
  fs::path page = fs::absolute(tmp_->path / "report" / "report.html");
  testing::TempDir profile("chromium-profile");
  fs::path shot = tmp_->path / "screenshot.png";
  auto r = testing::run("timeout 60 " + chromium +
                        " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                        " --disable-background-networking --disable-component-update --disable-sync"
                        " --enable-logging=stderr --v=0 --user-data-dir=" + profile.str() +
                        " --screenshot=" + shot.string() + " --window-size=1280,2000 file://" + page.string());
  ASSERT_EQ(r.status, 0) << r.out;
  // No console messages from the page (it has no scripts, so any is an error).
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    bool console = line.find(":CONSOLE") != std::string::npos;
    bool mentions_page = line.find("report.html") != std::string::npos || line.find("file://") != std::string::npos;
    EXPECT_FALSE(console || (mentions_page && line.find("ERROR") != std::string::npos)) << line;
  }
  ASSERT_TRUE(fs::exists(shot)) << r.out;
  auto img = render::read_png(shot);
  EXPECT_EQ(img.width, 1280);
  EXPECT_EQ(img.height, 2000);
  std::set<uint32_t> colours;
  size_t non_background = 0;
  const render::Rgb bg = img.at(2, 2);
  for (int y = 0; y < img.height; y += 2)
    for (int x = 0; x < img.width; x += 2) {
      auto c = img.at(x, y);
      colours.insert((uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b);
      if (!(c == bg)) ++non_background;
    }
  EXPECT_GT(colours.size(), 200u);  // text, charts, gem colours, GIF thumbnails
  EXPECT_GT(non_background, static_cast<size_t>(img.width * img.height / 4 / 20));  // > 5% of sampled pixels drawn
}

}  // namespace report_test

}  // namespace clips::report
