// `clips plan` on the IPC benchmark folders of ../shared/ipc (issue 64): a few
// folders parse and ground both their problems (among them the features
// they were refused for: derived predicates, union types, names run into
// variables, fluents undefined where no reachable action reads them, a
// grounding a size estimate refused), and quick ones are solved with the
// optimal cost Fast Downward's reference.tsv gives. Skipped without the
// collection ($CLIPS_IPC or ../shared/ipc). scripts/ipc-bench.sh runs them all.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "eval/support.hpp"

namespace clips::eval {
namespace {

namespace fs = std::filesystem;
using testing::clips_binary;
using testing::run;

std::string ipc_root() {
  if (const char* env = std::getenv("CLIPS_IPC")) return env;
  return clips::paths::source_dir() + "/../shared/ipc";
}

struct Reference {
  std::string problem, status;
  double cost = 0;
};

// reference.tsv: domain, problem, fd_search, fd_status, fd_cost, fd_seconds.
std::map<std::string, Reference> read_reference() {
  std::map<std::string, Reference> out;
  std::ifstream in(ipc_root() + "/reference.tsv");
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, '\t');) f.push_back(x);
    if (f.size() < 5) continue;
    out[f[0]] = Reference{f[1], f[3], f[4].empty() ? 0 : std::stod(f[4])};
  }
  return out;
}

// The domain file of problem file `p` in folder `dir`.
std::string domain_of(const fs::path& dir, const std::string& p) {
  const std::string stem = fs::path(p).stem().string();
  for (const std::string& name : {std::string("domain.pddl"), stem + "-domain.pddl", "domain_" + stem + ".pddl",
                                  "domain-" + stem + ".pddl"})
    if (fs::exists(dir / name)) return (dir / name).string();
  return "";
}

std::vector<std::string> problems_of(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (e.path().extension() == ".pddl" && n.find("domain") == std::string::npos) out.push_back(n);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The JSON line `clips plan --json` prints (its last line starting with '{').
nlohmann::json plan_json(const std::string& domain, const std::string& problem, const std::string& extra) {
  const auto r = run(clips_binary() + " plan --domain '" + domain + "' --problem '" + problem + "' --json " + extra);
  std::stringstream ss(r.out);
  std::string json;
  for (std::string line; std::getline(ss, line);)
    if (!line.empty() && line[0] == '{') json = line;
  try {
    return nlohmann::json::parse(json);
  } catch (const std::exception&) {
    return {{"error", r.out}};
  }
}

TEST(IpcPlan, FoldersParseAndGroundBothProblems) {
  if (!fs::exists(ipc_root() + "/reference.tsv")) GTEST_SKIP() << "no IPC collection at " << ipc_root();
  for (const std::string folder : {"psr-middle", "optical-telegraphs", "storage", "zenotravel", "elevators-opt11-strips",
                                   "freecell", "tetris-opt14-strips", "folding-opt23-adl", "airport-adl"}) {
    const fs::path dir = fs::path(ipc_root()) / folder;
    for (const std::string& p : problems_of(dir)) {
      const auto j = plan_json(domain_of(dir, p), (dir / p).string(), "--ground-only --max-seconds 60");
      EXPECT_EQ(j.value("status", ""), "grounded") << folder << "/" << p << ": " << j.dump();
      EXPECT_GT(j.value("actions", 0), 0) << folder << "/" << p;
    }
  }
}

TEST(IpcPlan, QuickFirstProblemsHaveFastDownwardsOptimalCost) {
  if (!fs::exists(ipc_root() + "/reference.tsv")) GTEST_SKIP() << "no IPC collection at " << ipc_root();
  const auto ref = read_reference();
  for (const std::string folder : {"blocks", "zenotravel", "storage", "psr-middle", "philosophers", "elevators-opt08-strips",
                                   "quantum-layout-opt23-strips", "sokoban-opt08-strips", "miconic-fulladl",
                                   "parcprinter-08-strips"}) {
    const auto it = ref.find(folder);
    ASSERT_NE(it, ref.end()) << folder;
    ASSERT_EQ(it->second.status, "solved") << folder;
    const fs::path dir = fs::path(ipc_root()) / folder;
    const auto j = plan_json(domain_of(dir, it->second.problem), (dir / it->second.problem).string(), "--max-seconds 120");
    EXPECT_EQ(j.value("status", ""), "success") << folder << ": " << j.dump();
    EXPECT_DOUBLE_EQ(j.value("cost", -1.0), it->second.cost) << folder;
  }
}

}  // namespace
}  // namespace clips::eval
