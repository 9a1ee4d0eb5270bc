#pragma once
// The worked example of docs/domains.md (the kitchen), read from the page
// itself, for the tests of sessions on a domain of one's own: its files as
// text, and a fresh folder holding them without any plan (plus a problem 2
// that has never had one).
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace clips::serve::testing {

// Every "<!-- file: PATH -->" block of docs/domains.md, by PATH.
inline std::map<std::string, std::string> docs_example_files() {
  std::ifstream in(std::string(CLIPS_SOURCE_DIR) + "/docs/domains.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  std::map<std::string, std::string> files;
  const std::string tag = "<!-- file: ";
  for (size_t at = doc.find(tag); at != std::string::npos; at = doc.find(tag, at + 1)) {
    const size_t name_end = doc.find(" -->", at);
    const std::string path = doc.substr(at + tag.size(), name_end - at - tag.size());
    const size_t fence = doc.find("```", name_end);
    const size_t body = doc.find('\n', fence) + 1;
    const size_t close = doc.find("\n```", body - 1);
    if (fence == std::string::npos || close == std::string::npos) throw std::runtime_error("docs/domains.md: " + path);
    files[path] = doc.substr(body, close + 1 - body);
  }
  return files;
}

// The kitchen's problem 2 (tests/serve/kitchen-2.pddl): the same kitchen, the
// cook at the counter and the helper in the pantry. No plan has ever been
// recorded for it.
inline const std::string& kitchen_problem_2() {
  static const std::string text = [] {
    std::ifstream in(std::string(CLIPS_SOURCE_DIR) + "/tests/serve/kitchen-2.pddl");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }();
  return text;
}

// A fresh folder "<tmp>/.../kitchen" with the kitchen's domain, pack, few-shot
// examples and problems 1 and 2, and no plans/ at all; removed with the object.
struct KitchenFolder {
  std::filesystem::path root;
  std::string dir;  // .../kitchen
  KitchenFolder() {
    static std::atomic<int> n{0};
    root = std::filesystem::temp_directory_path() /
           ("clips-kitchen-" + std::to_string(getpid()) + "-" + std::to_string(n++));
    dir = (root / "kitchen").string();
    for (const auto& [path, text] : docs_example_files()) {
      if (path.find("/plans/") != std::string::npos) continue;
      const auto full = root / path;
      std::filesystem::create_directories(full.parent_path());
      std::ofstream(full) << text;
    }
    std::ofstream(root / "kitchen" / "problems" / "2.pddl") << kitchen_problem_2();
  }
  ~KitchenFolder() {
    std::error_code ec;
    std::filesystem::remove_all(root, ec);
  }
  KitchenFolder(const KitchenFolder&) = delete;
  KitchenFolder& operator=(const KitchenFolder&) = delete;
};

}  // namespace clips::serve::testing
