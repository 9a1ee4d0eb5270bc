#pragma once
// A page's generated section, between "<!-- ID: begin (generated) -->" and
// "<!-- ID: end -->", checked against what the code makes of it; with
// CLIPS_UPDATE_DOCS=1 set the page is rewritten instead.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace clips::generated_docs {

// `page`: a path under the source folder ("docs/cli.md").
inline void expect_generated_section(const std::string& page, const std::string& id, const std::string& want) {
  const std::string path = std::string(CLIPS_SOURCE_DIR) + "/" + page;
  std::stringstream buf;
  buf << std::ifstream(path).rdbuf();
  std::string text = buf.str();
  const std::string begin = "<!-- " + id + ": begin (generated) -->\n", end = "<!-- " + id + ": end -->";
  const auto b = text.find(begin), e = text.find(end);
  ASSERT_NE(b, std::string::npos) << page << " has no " << begin;
  ASSERT_NE(e, std::string::npos) << page << " has no " << end;
  const std::string section = text.substr(b + begin.size(), e - b - begin.size());
  if (std::getenv("CLIPS_UPDATE_DOCS") && section != want) {
    text.replace(b + begin.size(), e - b - begin.size(), want);
    std::ofstream(path) << text;
    return;
  }
  EXPECT_EQ(section, want) << page << "'s " << id << " table is behind the code: rerun with CLIPS_UPDATE_DOCS=1";
}

}  // namespace clips::generated_docs
