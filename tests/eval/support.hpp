// Shared helpers of the eval tests: temp dirs and running the clips binary.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_paths.hpp"

namespace clips::eval::testing {

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The goal probabilities of a posterior in the engine's JSON form
// ({"goals": [{"goal", "p"}], ...}: `clips infer --json`'s steps), in order.
inline std::vector<double> goal_probabilities(const nlohmann::json& posterior) {
  std::vector<double> p;
  for (const auto& g : posterior.at("goals")) p.push_back(g.at("p").get<double>());
  return p;
}

inline std::string clips_binary() { return std::string(CLIPS_BINARY_DIR) + "/clips"; }
inline std::string examples_dkg() { return clips::paths::examples_dir() + "/doors-keys-gems"; }

// A fresh directory under the system temp dir, removed on destruction.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& tag) {
    std::random_device rd;
    path = std::filesystem::temp_directory_path() / ("clips-" + tag + "-" + std::to_string(rd()));
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::string str() const { return path.string(); }
};

// A scratch copy of the Doors-Keys-Gems examples dataset (`ds`), for tests
// that break or rewrite one of its files.
struct ExamplesCopy {
  TempDir dir;
  std::string ds = (dir.path / "dkg").string();
  explicit ExamplesCopy(const std::string& tag) : dir(tag) {
    std::filesystem::copy(examples_dkg(), ds, std::filesystem::copy_options::recursive);
  }
  std::filesystem::path file(const std::string& relative) const { return std::filesystem::path(ds) / relative; }
};

struct RunResult {
  int status = -1;
  std::string out;  // stdout and stderr, interleaved
};

inline RunResult run(const std::string& command) {
  RunResult r;
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// RFC 4180 records: quoted fields may hold commas, doubled quotes and newlines.
inline std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false, any = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    any = true;
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') field += '"', ++i;
      else if (c == '"') quoted = false;
      else field += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.push_back(field), field.clear();
    } else if (c == '\n') {
      row.push_back(field), field.clear();
      rows.push_back(row), row.clear();
      any = false;
    } else {
      field += c;
    }
  }
  if (any) row.push_back(field), rows.push_back(row);
  return rows;
}

}  // namespace clips::eval::testing
