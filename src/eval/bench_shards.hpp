#pragma once
// Sharded sweeps: `clips bench --shard K/N --out DIR` runs one of N disjoint
// parts of a dataset's plans (ShardSet in bench.hpp says which plans), and
// `clips bench merge` joins the parts' folders into the files one unsharded
// run would have written, without running any plan again.
//
// What makes that possible is DIR/outcomes.json, written beside the other
// bench files: every per-plan outcome at full precision (results.csv rounds
// to six digits, so it cannot give back the same means) and the run's
// identity, the settings that must agree between parts of one sweep.
#include <string>
#include <vector>

#include "eval/bench.hpp"

namespace clips::eval {

// The files `clips bench --out DIR` writes, in the order it writes them:
// outcomes.json last, so a folder that has it was written to the end.
const std::vector<std::string>& bench_file_names();

// Writes summary.json, results.csv, posteriors.csv and outcomes.json into
// `dir` (which must exist). Throws InputError naming a file it cannot write.
void write_bench_files(const BenchReport& report, const std::string& dir);

// outcomes.json: {"format": "clips-bench-outcomes", "version": 1,
// "run": {the identity: domain, dataset_fingerprint, clips_version,
// git_commit, seed, assistance, methods_requested, lm, speaker_rule,
// utterance_timing, qa_floor, chat_model, shard_count, selection},
// "shards_present": [K...], "dataset", "date", "wall_seconds", "max_rss_kb",
// "plans": [one object per PlanOutcome]}. Every PlanOutcome and MethodResult
// field is kept except the grounded action ids (MethodResult::actions; the
// printed `plan` has the same run) and the in-memory exception pointers.
// Numbers that are not finite are written as "nan", "inf" or "-inf".
std::string outcomes_json(const BenchReport& report);

// The identity fields of outcomes.json's "run" object, as written there.
nlohmann::ordered_json run_identity(const BenchReport& report);

// Reads a bench output folder back into a report: every file of
// bench_file_names() must be there, and outcomes.json well-formed. Throws
// InputError naming the folder, the file and the field.
BenchReport read_bench_part(const std::string& dir);
// The outcomes.json part of that: its text, named `file` in errors.
BenchReport read_bench_outcomes(const std::string& text, const std::string& file);

struct BenchPart {
  std::string dir;     // for error messages
  BenchReport report;  // read_bench_part(dir)
};

struct MergeOptions {
  // Merge even when some of the N shards are missing; the result says so
  // (ShardSet::missing, summary.json's "shards").
  bool allow_partial = false;
};

// One report from the parts of a sweep: plans in selection order, summary
// recomputed over all of them. Refuses (InputError naming the folder and the
// field) parts of different runs, a shard or a plan given twice, a part
// lacking one of its own plans, and, without allow_partial, missing shards.
// Timing: date is the earliest part's, wall_seconds the parts' sum (compute
// spent, not elapsed time), max_rss_kb the largest part's.
BenchReport merge_bench_parts(std::vector<BenchPart> parts, const MergeOptions& options);

}  // namespace clips::eval
