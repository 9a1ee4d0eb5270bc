// `clips bench merge` inputs (issue 46): the input is one shard's
// outcomes.json. It is read as `bench merge` reads a part, merged on its own
// (as with --allow-partial), and every file the merge writes is produced in
// memory: summary.json, results.csv, posteriors.csv, outcomes.json. Whatever
// the file says, it is refused with an InputError naming the field, or every
// output is produced without crashing; a merged report must read back.
#include "eval/bench.hpp"
#include "eval/bench_shards.hpp"
#include "fuzz/fuzz_target.hpp"
#include "util/error.hpp"

namespace {
constexpr size_t kMaxInputBytes = 65536;
}  // namespace

CLIPS_FUZZ_TARGET(bench_merge) {
  using namespace clips;
  if (size > kMaxInputBytes) return 0;
  eval::BenchReport merged;
  try {
    eval::BenchPart part{"<part>", eval::read_bench_outcomes(fuzz::as_text(data, size), "<part>/outcomes.json")};
    eval::MergeOptions options;
    options.allow_partial = true;
    std::vector<eval::BenchPart> parts;
    parts.push_back(std::move(part));
    merged = eval::merge_bench_parts(std::move(parts), options);
  } catch (const InputError&) {
    return 0;
  }
  (void)eval::summary_json(merged);
  (void)eval::results_csv(merged);
  (void)eval::posteriors_csv(merged);
  // What the merge writes reads back (a merged folder is itself a part).
  try {
    (void)eval::read_bench_outcomes(eval::outcomes_json(merged), "<merged>/outcomes.json");
  } catch (const InputError&) {
    __builtin_trap();
  }
  return 0;
}
