// Replays every seed (fuzz/corpus/<name>/) and every kept crasher
// (fuzz/regressions/<name>/) through the fuzz targets' own functions, so the
// normal build checks that none of them crashes or throws an unexpected
// exception (the targets catch only the documented input errors).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

#include "fuzz/fuzz_target.hpp"

CLIPS_FUZZ_DECLARE(sexpr);
CLIPS_FUZZ_DECLARE(pddl);
CLIPS_FUZZ_DECLARE(plan);
CLIPS_FUZZ_DECLARE(dataset);
CLIPS_FUZZ_DECLARE(goalset);
CLIPS_FUZZ_DECLARE(utterance);
CLIPS_FUZZ_DECLARE(completions);
CLIPS_FUZZ_DECLARE(chat);
CLIPS_FUZZ_DECLARE(serve);
CLIPS_FUZZ_DECLARE(stdio);
CLIPS_FUZZ_DECLARE(pack);
CLIPS_FUZZ_DECLARE(pack_roles);
CLIPS_FUZZ_DECLARE(cost_profiles);
CLIPS_FUZZ_DECLARE(quantified_goals);
CLIPS_FUZZ_DECLARE(bench_merge);

namespace fs = std::filesystem;

namespace {

using Target = int (*)(const uint8_t*, size_t);

struct Case {
  const char* name;
  Target run;
};

// So that test names and listings show the target, not the struct's bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

const Case kTargets[] = {
    {"sexpr", clips_fuzz_sexpr},         {"pddl", clips_fuzz_pddl},
    {"plan", clips_fuzz_plan},           {"dataset", clips_fuzz_dataset},
    {"utterance", clips_fuzz_utterance}, {"completions", clips_fuzz_completions},
    {"chat", clips_fuzz_chat},           {"serve", clips_fuzz_serve},
    {"pack", clips_fuzz_pack},           {"bench_merge", clips_fuzz_bench_merge},
    {"goalset", clips_fuzz_goalset},     {"stdio", clips_fuzz_stdio},
    {"pack_roles", clips_fuzz_pack_roles}, {"cost_profiles", clips_fuzz_cost_profiles},
    {"quantified_goals", clips_fuzz_quantified_goals},
};

// Runs every file of `dir` (if it exists) through `run`; returns how many.
int replay(const fs::path& dir, Target run) {
  if (!fs::is_directory(dir)) return 0;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    std::ifstream in(f, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), 0);
  }
  return static_cast<int>(files.size());
}

class FuzzReplay : public ::testing::TestWithParam<Case> {};

TEST_P(FuzzReplay, SeedsAndRegressionsRunClean) {
  const fs::path root = fs::path(CLIPS_SOURCE_DIR) / "fuzz";
  const int seeds = replay(root / "corpus" / GetParam().name, GetParam().run);
  const int regressions = replay(root / "regressions" / GetParam().name, GetParam().run);
  // Every target ships seeds; an empty folder would make this test vacuous.
  EXPECT_GT(seeds, 0) << "no seed inputs in fuzz/corpus/" << GetParam().name;
  RecordProperty("seeds", seeds);
  RecordProperty("regressions", regressions);
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay, ::testing::ValuesIn(kTargets),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
