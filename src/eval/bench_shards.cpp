#include "eval/bench_shards.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "util/error.hpp"
#include "util/program_name.hpp"

namespace clips::eval {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;
using nlohmann::json;

namespace {

constexpr const char* kFormat = "clips-bench-outcomes";
constexpr int kFormatVersion = 1;

// ---- writing ---------------------------------------------------------------

// JSON has no NaN or infinity (nlohmann would write null): such values are
// written as strings so that they read back as the same double.
ojson real(double v) {
  if (std::isfinite(v)) return v;
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

ojson reals(const std::vector<double>& vs) {
  ojson out = ojson::array();
  for (double v : vs) out.push_back(real(v));
  return out;
}

ojson matrix(const std::vector<std::vector<double>>& rows) {
  ojson out = ojson::array();
  for (const auto& row : rows) out.push_back(reals(row));
  return out;
}

ojson method_json(const MethodResult& m) {
  ojson options = ojson::object();
  for (const auto& [name, p] : m.options) options[name] = real(p);
  return {{"method", m.method},
          {"p_true_goal", m.p_true_goal ? real(*m.p_true_goal) : ojson()},
          {"goal_posterior", reals(m.goal_posterior)},
          {"posterior_steps", matrix(m.posterior_steps)},
          {"precision", real(m.precision)},
          {"recall", real(m.recall)},
          {"plan_length", real(m.plan_length)},
          {"human_cost", real(m.human_cost)},
          {"plan_cost", real(m.plan_cost)},
          {"has_relative", m.has_relative},
          {"rel_plan_length", real(m.rel_plan_length)},
          {"rel_human_cost", real(m.rel_human_cost)},
          {"goal_success", real(m.goal_success)},
          {"options", options},
          {"plan", m.plan},
          {"decision_seconds", reals(m.decision_seconds)},
          {"seconds", real(m.seconds)},
          {"error", m.error},
          {"notes", m.notes},
          {"request_done", m.request_done ? ojson(*m.request_done) : ojson()}};
}

ojson plan_json(const PlanOutcome& p) {
  ojson methods = ojson::array();
  for (const auto& m : p.methods) methods.push_back(method_json(m));
  return {{"plan", p.plan_id},
          {"goals", p.goals},
          {"true_goal", p.true_goal},
          {"true_options", p.true_options},
          {"goal_posterior_steps", matrix(p.goal_posterior_steps)},
          {"step_seconds", reals(p.step_seconds)},
          {"step_work_seconds", reals(p.step_work_seconds)},
          {"inference_threads", p.inference_threads},
          {"utterance_warnings", p.utterance_warnings},
          {"split", p.split},
          {"categories", p.categories},
          {"instruction_step", p.instruction_step},
          {"requested", p.requested},
          {"seconds", real(p.seconds)},
          {"error", p.error},
          {"methods", methods}};
}

// ---- reading ---------------------------------------------------------------

// Reads the fields of one outcomes.json; every error names the file and the
// field's path (e.g. plans[3].methods[1].precision).
class FieldReader {
 public:
  explicit FieldReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(fmt::format("{}: {}: {}", file_, field, what));
  }

  const json& get(const json& obj, const std::string& key, const std::string& path) const {
    if (!obj.is_object()) fail(path, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(join(path, key), "missing");
    return *it;
  }
  std::string text(const json& obj, const std::string& key, const std::string& path) const {
    const json& v = get(obj, key, path);
    if (!v.is_string()) fail(join(path, key), "expected a string, got " + v.dump());
    return v.get<std::string>();
  }
  bool flag(const json& obj, const std::string& key, const std::string& path) const {
    const json& v = get(obj, key, path);
    if (!v.is_boolean()) fail(join(path, key), "expected true or false, got " + v.dump());
    return v.get<bool>();
  }
  long long integer(const json& obj, const std::string& key, const std::string& path) const {
    const json& v = get(obj, key, path);
    if (!v.is_number_integer()) fail(join(path, key), "expected an integer, got " + v.dump());
    return v.get<long long>();
  }
  uint64_t unsigned_integer(const json& obj, const std::string& key, const std::string& path) const {
    const json& v = get(obj, key, path);
    if (!v.is_number_unsigned()) fail(join(path, key), "expected a non-negative integer, got " + v.dump());
    return v.get<uint64_t>();
  }
  double real(const json& obj, const std::string& key, const std::string& path) const {
    return real_value(get(obj, key, path), join(path, key));
  }
  std::optional<double> optional_real(const json& obj, const std::string& key, const std::string& path) const {
    const json& v = get(obj, key, path);
    if (v.is_null()) return std::nullopt;
    return real_value(v, join(path, key));
  }
  std::vector<std::string> texts(const json& obj, const std::string& key, const std::string& path) const {
    std::vector<std::string> out;
    const std::string here = join(path, key);
    for (const auto& [i, v] : items(get(obj, key, path), here)) {
      if (!v->is_string()) fail(i, "expected a string, got " + v->dump());
      out.push_back(v->get<std::string>());
    }
    return out;
  }
  std::vector<double> reals(const json& obj, const std::string& key, const std::string& path) const {
    return reals_of(get(obj, key, path), join(path, key));
  }
  std::vector<std::vector<double>> matrix(const json& obj, const std::string& key, const std::string& path) const {
    std::vector<std::vector<double>> out;
    const std::string here = join(path, key);
    for (const auto& [i, row] : items(get(obj, key, path), here)) out.push_back(reals_of(*row, i));
    return out;
  }
  // The elements of an array with their paths ("plans[3]").
  std::vector<std::pair<std::string, const json*>> items(const json& array, const std::string& path) const {
    if (!array.is_array()) fail(path, "expected an array, got " + array.dump().substr(0, 80));
    std::vector<std::pair<std::string, const json*>> out;
    for (size_t i = 0; i < array.size(); ++i) out.emplace_back(fmt::format("{}[{}]", path, i), &array[i]);
    return out;
  }
  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

 private:
  double real_value(const json& v, const std::string& path) const {
    if (v.is_number()) return v.get<double>();
    if (v == "nan") return std::nan("");
    if (v == "inf") return HUGE_VAL;
    if (v == "-inf") return -HUGE_VAL;
    fail(path, "expected a number, got " + v.dump());
  }
  std::vector<double> reals_of(const json& array, const std::string& path) const {
    std::vector<double> out;
    for (const auto& [i, v] : items(array, path)) out.push_back(real_value(*v, i));
    return out;
  }
  std::string file_;
};

MethodResult read_method(const FieldReader& in, const json& j, const std::string& at) {
  MethodResult m;
  m.method = in.text(j, "method", at);
  m.p_true_goal = in.optional_real(j, "p_true_goal", at);
  m.goal_posterior = in.reals(j, "goal_posterior", at);
  m.posterior_steps = in.matrix(j, "posterior_steps", at);
  m.precision = in.real(j, "precision", at);
  m.recall = in.real(j, "recall", at);
  m.plan_length = in.real(j, "plan_length", at);
  m.human_cost = in.real(j, "human_cost", at);
  m.plan_cost = in.real(j, "plan_cost", at);
  m.has_relative = in.flag(j, "has_relative", at);
  m.rel_plan_length = in.real(j, "rel_plan_length", at);
  m.rel_human_cost = in.real(j, "rel_human_cost", at);
  m.goal_success = in.real(j, "goal_success", at);
  const json& options = in.get(j, "options", at);
  if (!options.is_object()) in.fail(FieldReader::join(at, "options"), "expected an object of option: probability");
  for (auto it = options.begin(); it != options.end(); ++it)
    m.options[it.key()] = in.real(options, it.key(), FieldReader::join(at, "options"));
  m.plan = in.texts(j, "plan", at);
  m.decision_seconds = in.reals(j, "decision_seconds", at);
  m.seconds = in.real(j, "seconds", at);
  m.error = in.text(j, "error", at);
  m.notes = in.texts(j, "notes", at);
  // Written before requests were counted: none.
  if (j.contains("request_done") && !j["request_done"].is_null()) m.request_done = in.flag(j, "request_done", at);
  return m;
}

PlanOutcome read_plan(const FieldReader& in, const json& j, const std::string& at) {
  PlanOutcome p;
  p.plan_id = in.text(j, "plan", at);
  p.goals = in.texts(j, "goals", at);
  const long long true_goal = in.integer(j, "true_goal", at);
  // Checked against the goals in check_plan; here only kept from wrapping into range.
  if (true_goal < -1 || true_goal > 1'000'000)
    in.fail(FieldReader::join(at, "true_goal"), fmt::format("{} is not the index of one of the plan's goals", true_goal));
  p.true_goal = static_cast<int>(true_goal);
  p.true_options = in.texts(j, "true_options", at);
  p.goal_posterior_steps = in.matrix(j, "goal_posterior_steps", at);
  // Step times came later (issue 43): parts written before have none.
  if (j.is_object() && j.contains("step_seconds")) {
    p.step_seconds = in.reals(j, "step_seconds", at);
    p.step_work_seconds = in.reals(j, "step_work_seconds", at);
    p.inference_threads = static_cast<int>(in.integer(j, "inference_threads", at));
  }
  p.utterance_warnings = in.texts(j, "utterance_warnings", at);
  // Outcomes written before instruction tables existed have none.
  if (j.contains("split")) p.split = in.text(j, "split", at);
  if (j.contains("categories")) p.categories = in.texts(j, "categories", at);
  if (j.contains("instruction_step")) p.instruction_step = static_cast<int>(in.integer(j, "instruction_step", at));
  if (j.contains("requested")) p.requested = in.text(j, "requested", at);
  p.seconds = in.real(j, "seconds", at);
  p.error = in.text(j, "error", at);
  const std::string here = FieldReader::join(at, "methods");
  for (const auto& [i, m] : in.items(in.get(j, "methods", at), here)) p.methods.push_back(read_method(in, *m, i));
  return p;
}

// What later steps index by: one goal posterior entry per goal, the true
// goal one of the goals, probabilities within [0, 1] (NaN allowed where a
// method had no value). A plan outcome written by `clips bench` always holds;
// a hand-edited or damaged one is refused here, naming the field.
constexpr double kMaxMeasure = 1e12;

void check_plan(const FieldReader& in, const PlanOutcome& p, const std::string& at) {
  const size_t n = p.goals.size();
  auto probability = [&](double v, const std::string& field) {
    if (!(std::isnan(v) || (v >= -1e-9 && v <= 1 + 1e-9)))
      in.fail(field, fmt::format("{} is not a probability (from 0 to 1)", v));
  };
  auto row = [&](const std::vector<double>& r, const std::string& field) {
    if (r.size() != n)
      in.fail(field, fmt::format("has {} entries, but the plan has {} goals (goals)", r.size(), n));
    for (size_t g = 0; g < r.size(); ++g) probability(r[g], fmt::format("{}[{}]", field, g));
  };
  if (!p.error.empty() && n == 0) return;  // a plan that failed before its goals were known
  if (n == 0) in.fail(FieldReader::join(at, "goals"), "is empty (an evaluated plan has at least one goal)");
  std::vector<std::string> sorted = p.goals;
  std::sort(sorted.begin(), sorted.end());
  if (auto dup = std::adjacent_find(sorted.begin(), sorted.end()); dup != sorted.end())
    in.fail(FieldReader::join(at, "goals"), "lists goal " + *dup + " twice");
  if (p.true_goal < 0 || static_cast<size_t>(p.true_goal) >= n)
    in.fail(FieldReader::join(at, "true_goal"),
            fmt::format("{} is not the index of one of the plan's {} goals (0 to {})", p.true_goal, n, n - 1));
  for (size_t t = 0; t < p.goal_posterior_steps.size(); ++t)
    row(p.goal_posterior_steps[t], fmt::format("{}.goal_posterior_steps[{}]", at, t));
  // Lengths, costs, their ratios and times: NaN (no value) or from 0 to a
  // bound no run reaches (a plan of 100,000 steps at the largest action cost,
  // 1e6, costs 1e11), so that an absurd value cannot blow up the report.
  auto measure = [&](double v, const std::string& field) {
    if (!(std::isnan(v) || (v >= 0 && v <= kMaxMeasure)))
      in.fail(field, fmt::format("{} is not a length, cost or time (from 0 to {:g})", v, kMaxMeasure));
  };
  for (size_t k = 0; k < p.methods.size(); ++k) {
    const MethodResult& m = p.methods[k];
    const std::string mat = fmt::format("{}.methods[{}]", at, k);
    if (!is_method_name(m.method))
      in.fail(mat + ".method", "'" + m.method.substr(0, 80) + "' is not a method clips bench runs");
    if (m.p_true_goal) probability(*m.p_true_goal, mat + ".p_true_goal");
    probability(m.precision, mat + ".precision");
    probability(m.recall, mat + ".recall");
    probability(m.goal_success, mat + ".goal_success");
    measure(m.plan_length, mat + ".plan_length");
    measure(m.human_cost, mat + ".human_cost");
    measure(m.plan_cost, mat + ".plan_cost");
    measure(m.rel_plan_length, mat + ".rel_plan_length");
    measure(m.rel_human_cost, mat + ".rel_human_cost");
    measure(m.seconds, mat + ".seconds");
    for (const auto& [option, v] : m.options) probability(v, mat + ".options." + option.substr(0, 80));
    for (size_t d = 0; d < m.decision_seconds.size(); ++d)
      measure(m.decision_seconds[d], fmt::format("{}.decision_seconds[{}]", mat, d));
    if (!m.goal_posterior.empty()) row(m.goal_posterior, mat + ".goal_posterior");
    for (size_t t = 0; t < m.posterior_steps.size(); ++t)
      row(m.posterior_steps[t], fmt::format("{}.posterior_steps[{}]", mat, t));
  }
}

// The run's identity back into the report's fields.
void read_identity(const FieldReader& in, const json& run, BenchReport& r) {
  const std::string at = "run";
  r.domain = in.text(run, "domain", at);
  r.fingerprint = in.text(run, "dataset_fingerprint", at);
  r.clips_version = in.text(run, "clips_version", at);
  r.git_commit = in.text(run, "git_commit", at);
  r.seed = in.unsigned_integer(run, "seed", at);
  r.assistance = in.text(run, "assistance", at);
  r.methods_requested = in.texts(run, "methods_requested", at);
  r.lm = in.text(run, "lm", at);
  r.speaker_rule = in.text(run, "speaker_rule", at);
  r.utterance_timing = in.text(run, "utterance_timing", at);
  r.qa_floor = in.text(run, "qa_floor", at);
  r.assistant_turns = in.text(run, "assistant_turns", at);
  r.chat_model = in.text(run, "chat_model", at);
  const long long count = in.integer(run, "shard_count", at);
  if (count < 1 || count > 1'000'000)
    in.fail("run.shard_count", fmt::format("must be from 1 to 1000000, got {}", count));
  r.shards.count = static_cast<int>(count);
  r.selection = in.texts(run, "selection", at);
  std::vector<std::string> sorted = r.selection;
  std::sort(sorted.begin(), sorted.end());
  if (auto dup = std::adjacent_find(sorted.begin(), sorted.end()); dup != sorted.end())
    in.fail("run.selection", "plan " + *dup + " is listed twice");
}

std::vector<int> read_present(const FieldReader& in, const json& j, int count) {
  std::vector<int> present;
  for (const auto& [i, v] : in.items(in.get(j, "shards_present", ""), "shards_present")) {
    if (!v->is_number_integer() || v->get<long long>() < 1 || v->get<long long>() > count)
      in.fail(i, fmt::format("expected a shard number from 1 to {}, got {}", count, v->dump()));
    present.push_back(v->get<int>());
  }
  if (present.empty()) in.fail("shards_present", "is empty");
  std::sort(present.begin(), present.end());
  if (std::adjacent_find(present.begin(), present.end()) != present.end())
    in.fail("shards_present", "lists a shard twice");
  return present;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) throw InputError("cannot read " + path.string());
  return text.str();
}

// ---- merging ---------------------------------------------------------------

std::string shard_list(const std::vector<int>& ks) {
  std::string out;
  for (int k : ks) out += (out.empty() ? "" : ", ") + std::to_string(k);
  return out;
}

std::string brief(const ojson& v) {
  const std::string text = v.dump();
  return text.size() <= 80 ? text : text.substr(0, 77) + "...";
}

// How a part's plan selection differs from the first part's, briefly.
std::string selection_difference(const std::vector<std::string>& theirs, const std::vector<std::string>& ours) {
  if (theirs.size() != ours.size())
    return fmt::format("has {} plans, the first part's {}", theirs.size(), ours.size());
  size_t i = 0;
  while (i < theirs.size() && theirs[i] == ours[i]) ++i;
  return fmt::format("differs at position {}: plan {} where the first part has {}", i, theirs[i], ours[i]);
}

// Every identity field of every part must equal the first part's.
void check_same_run(const std::vector<BenchPart>& parts) {
  const ojson first = run_identity(parts.front().report);
  for (size_t i = 1; i < parts.size(); ++i) {
    const ojson other = run_identity(parts[i].report);
    for (auto it = first.begin(); it != first.end(); ++it) {
      const std::string& field = it.key();
      const ojson& value = it.value();
      if (other.at(field) == value) continue;
      const std::string difference = field == "selection"
                                         ? selection_difference(parts[i].report.selection, parts.front().report.selection)
                                         : fmt::format("is {}, but {}/outcomes.json has {}", brief(other.at(field)),
                                                       parts.front().dir, brief(value));
      throw InputError(fmt::format("{}/outcomes.json: {} {}: these folders are parts of different runs and cannot "
                                   "be merged",
                                   parts[i].dir, field, difference));
    }
  }
}

// Which part holds each shard K; a K in two parts is refused.
std::map<int, size_t> shard_owners(const std::vector<BenchPart>& parts) {
  std::map<int, size_t> owner;
  for (size_t i = 0; i < parts.size(); ++i)
    for (int k : parts[i].report.shards.present) {
      auto [it, fresh] = owner.emplace(k, i);
      if (!fresh)
        throw InputError(fmt::format("shard {} of {} is in both {} and {}: give each shard once", k,
                                     parts[i].report.shards.count, parts[it->second].dir, parts[i].dir));
    }
  return owner;
}

// The plans of every part by id, with the part that holds each; a plan in two
// parts (or twice in one) is refused.
std::map<std::string, std::pair<const PlanOutcome*, size_t>> plans_by_id(const std::vector<BenchPart>& parts) {
  std::map<std::string, std::pair<const PlanOutcome*, size_t>> by_id;
  for (size_t i = 0; i < parts.size(); ++i)
    for (const PlanOutcome& p : parts[i].report.plans) {
      auto [it, fresh] = by_id.emplace(p.plan_id, std::pair{&p, i});
      if (!fresh)
        throw InputError(fmt::format("plan {} is in both {} and {}: overlapping parts cannot be merged", p.plan_id,
                                     parts[it->second.second].dir, parts[i].dir));
    }
  return by_id;
}

// The parts' plans in selection order. Each plan of a present shard must
// come from the part that holds that shard, and no part may hold more.
std::vector<PlanOutcome> plans_in_selection_order(const std::vector<BenchPart>& parts, const BenchReport& merged,
                                                  const std::map<int, size_t>& owner) {
  auto by_id = plans_by_id(parts);
  std::vector<PlanOutcome> plans;
  for (size_t pos = 0; pos < merged.selection.size(); ++pos) {
    const std::string& id = merged.selection[pos];
    const int k = ShardSet::of_position(pos, merged.shards.count);
    const auto holder = owner.find(k);
    if (holder == owner.end()) continue;
    const auto found = by_id.find(id);
    if (found == by_id.end())
      throw InputError(fmt::format("{}/outcomes.json: plans: plan {} of shard {} is missing", parts[holder->second].dir,
                                   id, k));
    if (found->second.second != holder->second)
      throw InputError(fmt::format("{}/outcomes.json: plans: plan {} belongs to shard {}, which is {}",
                                   parts[found->second.second].dir, id, k, parts[holder->second].dir));
    plans.push_back(*found->second.first);
    by_id.erase(found);
  }
  if (!by_id.empty()) {
    const auto& [id, where] = *by_id.begin();
    throw InputError(fmt::format("{}/outcomes.json: plans: plan {} is not one of the sweep's plans of shard(s) {}",
                                 parts[where.second].dir, id, shard_list(parts[where.second].report.shards.present)));
  }
  return plans;
}

}  // namespace

const std::vector<std::string>& bench_file_names() {
  static const std::vector<std::string> names = {"summary.json", "results.csv", "posteriors.csv", "outcomes.json"};
  return names;
}

void write_bench_files(const BenchReport& r, const std::string& dir) {
  for (const std::string& name : bench_file_names()) {
    const std::string text = name == "summary.json"   ? summary_json(r)
                             : name == "results.csv"  ? results_csv(r)
                             : name == "posteriors.csv" ? posteriors_csv(r)
                                                        : outcomes_json(r);
    const std::string path = (fs::path(dir) / name).string();
    std::ofstream f(path);
    if (!(f << text) || !f.flush()) throw InputError("cannot write " + path);
  }
}

ojson run_identity(const BenchReport& r) {
  return {{"domain", r.domain},
          {"dataset_fingerprint", r.fingerprint},
          {"clips_version", r.clips_version},
          {"git_commit", r.git_commit},
          {"seed", r.seed},
          {"assistance", r.assistance},
          {"methods_requested", r.methods_requested},
          {"lm", r.lm},
          {"speaker_rule", r.speaker_rule},
          {"utterance_timing", r.utterance_timing},
          {"qa_floor", r.qa_floor},
          {"assistant_turns", r.assistant_turns},
          {"chat_model", r.chat_model},
          {"shard_count", r.shards.count},
          {"selection", r.selection}};
}

std::string outcomes_json(const BenchReport& r) {
  ojson plans = ojson::array();
  for (const auto& p : r.plans) plans.push_back(plan_json(p));
  const ojson j = {{"format", kFormat},
                   {"version", kFormatVersion},
                   {"run", run_identity(r)},
                   {"shards_present", r.shards.present},
                   {"dataset", r.dataset},
                   {"date", r.started_utc},
                   {"wall_seconds", real(r.wall_seconds)},
                   {"max_rss_kb", r.max_rss_kb},
                   {"plans", plans}};
  return j.dump(1) + "\n";
}

BenchReport read_bench_part(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir + ": no such folder (a shard's --out folder was expected)");
  for (const std::string& name : bench_file_names())
    if (!fs::exists(fs::path(dir) / name, ec))
      throw InputError(fmt::format("{}: {} is missing; a part needs all of summary.json, results.csv, "
                                   "posteriors.csv and outcomes.json (did its `{} bench --out` finish?)",
                                   dir, name, util::program_name()));
  const std::string file = (fs::path(dir) / "outcomes.json").string();
  return read_bench_outcomes(read_file(file), file);
}

BenchReport read_bench_outcomes(const std::string& text, const std::string& file) {
  const FieldReader in(file);
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) throw InputError(file + ": not valid JSON");
  if (!j.is_object() || !j.contains("format") || j["format"] != kFormat)
    in.fail("format", std::string("expected \"") + kFormat + "\"");
  if (in.integer(j, "version", "") != kFormatVersion)
    in.fail("version", fmt::format("this clips reads version {} only", kFormatVersion));
  BenchReport r;
  read_identity(in, in.get(j, "run", ""), r);
  r.shards.present = read_present(in, j, r.shards.count);
  r.dataset = in.text(j, "dataset", "");
  r.started_utc = in.text(j, "date", "");
  r.wall_seconds = in.real(j, "wall_seconds", "");
  r.max_rss_kb = static_cast<long>(in.integer(j, "max_rss_kb", ""));
  for (const auto& [i, p] : in.items(in.get(j, "plans", ""), "plans")) {
    r.plans.push_back(read_plan(in, *p, i));
    check_plan(in, r.plans.back(), i);
  }
  return r;
}

BenchReport merge_bench_parts(std::vector<BenchPart> parts, const MergeOptions& options) {
  if (parts.empty()) throw InputError("nothing to merge: give the folders of the shards");
  // In shard order, so that the result does not depend on the folders' order.
  std::stable_sort(parts.begin(), parts.end(), [](const BenchPart& a, const BenchPart& b) {
    return a.report.shards.present.front() < b.report.shards.present.front();
  });
  check_same_run(parts);
  const std::map<int, size_t> owner = shard_owners(parts);
  BenchReport merged = parts.front().report;
  merged.plans.clear();
  merged.shards.present.clear();
  for (const auto& [k, part] : owner) merged.shards.present.push_back(k);
  merged.plans = plans_in_selection_order(parts, merged, owner);
  const std::vector<int> missing = merged.shards.missing();
  if (!missing.empty() && !options.allow_partial)
    throw InputError(fmt::format("shard{} {} of {} {} missing (the parts hold {}); pass --allow-partial to merge "
                                 "anyway",
                                 missing.size() > 1 ? "s" : "", shard_list(missing), merged.shards.count,
                                 missing.size() > 1 ? "are" : "is", shard_list(merged.shards.present)));
  merged.wall_seconds = 0;
  for (const BenchPart& p : parts) {
    merged.started_utc = std::min(merged.started_utc, p.report.started_utc);
    merged.wall_seconds += p.report.wall_seconds;
    merged.max_rss_kb = std::max(merged.max_rss_kb, p.report.max_rss_kb);
  }
  summarise(merged);
  return merged;
}

}  // namespace clips::eval
