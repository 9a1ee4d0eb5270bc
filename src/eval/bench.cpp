#include "eval/bench.hpp"

#include "eval/breakdown.hpp"

#include <fmt/core.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <mutex>
#include <set>
#include <nlohmann/json.hpp>
#include <thread>

#include "eval/methods.hpp"
#include "commands/fewshot.hpp"
#include "language/listener.hpp"
#include "language/lm_domain.hpp"
#include "pddl/parser.hpp"
#include "util/hash.hpp"
#include "util/numbered_names.hpp"
#include "util/version.hpp"

namespace clips::eval {

namespace {

const std::vector<std::string> kMetricNames = {"p_true_goal", "assist_precision", "assist_recall",
                                               "rel_plan_length", "rel_human_cost", "goal_success"};

void progress_line(int done, int total, double secs, bool tty) {
  if (tty) {
    int width = 30;
    int filled = total ? done * width / total : width;
    fmt::print(stderr, "\r[{}{}] {}/{} plans  {:.1f} s", std::string(filled, '#'), std::string(width - filled, '.'), done,
               total, secs);
    if (done == total) fmt::print(stderr, "\n");
  } else {
    fmt::print(stderr, "bench: {}/{} plans done, {:.1f} s\n", done, total, secs);
  }
}

// "a, b, c", at most `max` names then "... (N in all)".
std::string name_list(const std::vector<std::string>& names, size_t max = 20) {
  std::string out;
  for (size_t i = 0; i < names.size() && i < max; ++i) out += (i ? ", " : "") + names[i];
  if (names.size() > max) out += fmt::format(", ... ({} in all)", names.size());
  return out;
}

// Unknown plan ids and method names are errors before any plan runs.
void check_selection(const data::Dataset& ds, const BenchOptions& opts) {
  std::vector<std::string> ids, unknown;
  for (auto& p : ds.plans()) ids.push_back(p.id);
  for (auto& id : opts.plans)
    for (auto& b : ds.broken_plans())
      if (b.id == id) throw InputError("--plans: plan " + id + " could not be loaded: " + b.error);
  for (auto& id : opts.plans)
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) unknown.push_back(id);
  if (!unknown.empty())
    throw InputError(fmt::format("--plans: unknown plan id{} {} in {}; valid ids: {}", unknown.size() > 1 ? "s" : "",
                                 name_list(unknown), opts.dataset, name_list(ids)));
  const auto known = known_methods(ds.pack());
  unknown.clear();
  for (auto& m : opts.experiment.methods)
    if (std::find(known.begin(), known.end(), m) == known.end()) unknown.push_back(m);
  if (!unknown.empty())
    throw InputError(fmt::format("--methods: unknown method{} {} for a {} dataset; valid methods: {}",
                                 unknown.size() > 1 ? "s" : "", name_list(unknown), ds.pack().name(),
                                 name_list(known, known.size())));
}

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string csv_quote(const std::string& s) {
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

std::string dataset_fingerprint(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files = {fs::path(dir) / "domain.pddl"};
  std::vector<fs::path> problems;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(fs::path(dir) / "problems", ec))
    if (e.path().extension() == ".pddl") problems.push_back(e.path());
  std::sort(problems.begin(), problems.end());
  files.insert(files.end(), problems.begin(), problems.end());
  std::uint64_t h = util::kFnv64Offset;
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) continue;
    std::stringstream bytes;
    bytes << in.rdbuf();
    const std::string name = f.filename().string();
    h = util::fnv1a64(name, h);
    h = util::fnv1a64(std::string_view("\0", 1), h);
    h = util::fnv1a64(bytes.str(), h);
  }
  return fmt::format("{:016x}", h);
}

bool paper_has_method(const nlohmann::json& paper_all, const std::string& domain, const std::string& method) {
  return paper_all.is_object() && paper_all.contains(domain) && paper_all[domain].is_object() &&
         paper_all[domain].contains(method);
}

const nlohmann::json* paper_results_for(const BenchReport& r, const nlohmann::json& paper_all) {
  if (!paper_all.is_object() || !paper_all.contains(r.domain)) return nullptr;
  const auto fp = paper_all.find("_fingerprints");
  if (fp == paper_all.end() || !fp->is_object() || !fp->contains(r.domain)) return nullptr;
  const auto& known = (*fp)[r.domain];
  const auto matches = [&](const nlohmann::json& v) { return v.is_string() && v.get<std::string>() == r.fingerprint; };
  bool ok = matches(known);
  if (known.is_array())
    for (const auto& v : known) ok |= matches(v);
  return ok ? &paper_all[r.domain] : nullptr;
}

bool ShardSet::holds_position(size_t position) const {
  return std::binary_search(present.begin(), present.end(), of_position(position, count));
}

std::vector<int> ShardSet::missing() const {
  std::vector<int> out;
  for (int k = 1; k <= count; ++k)
    if (!std::binary_search(present.begin(), present.end(), k)) out.push_back(k);
  return out;
}

std::string partial_note(const BenchReport& r) {
  if (!r.shards.partial()) return "";
  const auto join = [](const std::vector<int>& ks) {
    std::string out;
    for (int k : ks) out += (out.empty() ? "" : ", ") + std::to_string(k);
    return out;
  };
  return fmt::format("partial: shard{} {} of {} ({} of the sweep's {} plans); missing: {}",
                     r.shards.present.size() > 1 ? "s" : "", join(r.shards.present), r.shards.count, r.plans.size(),
                     r.selection.size(), join(r.shards.missing()));
}

namespace {

// The sweep's plans before sharding: those to evaluate, in dataset order, and
// the unloadable ones reported after them as failed plans (only without
// --plans; tutorial plans, demo*, are not evaluated).
struct Selection {
  std::vector<const data::PlanRecord*> plans;
  std::vector<const data::BrokenPlan*> broken;
  std::vector<std::string> ids() const {
    std::vector<std::string> out;
    for (auto* p : plans) out.push_back(p->id);
    for (auto* b : broken) out.push_back(b->id);
    return out;
  }
};

Selection select_plans(const data::Dataset& ds, const BenchOptions& opts) {
  Selection s;
  for (auto& p : ds.plans()) {
    bool wanted = opts.plans.empty() ? p.evaluated
                                     : std::find(opts.plans.begin(), opts.plans.end(), p.id) != opts.plans.end();
    if (wanted) s.plans.push_back(&p);
  }
  if (opts.plans.empty())
    for (auto& b : ds.broken_plans())
      if (b.id.rfind("demo", 0) != 0) s.broken.push_back(&b);
  return s;
}

// The part of the selection that the report's shards hold, positions kept.
Selection shard_part(const Selection& all, const ShardSet& shards) {
  Selection mine;
  for (size_t i = 0; i < all.plans.size(); ++i)
    if (shards.holds_position(i)) mine.plans.push_back(all.plans[i]);
  for (size_t j = 0; j < all.broken.size(); ++j)
    if (shards.holds_position(all.plans.size() + j)) mine.broken.push_back(all.broken[j]);
  return mine;
}

// The chat model behind the multimodal baseline when it will run, else "".
std::string multimodal_model(const ExperimentOptions& e) {
  const bool requested = std::find(e.methods.begin(), e.methods.end(), baseline_choices().name(Baseline::Multimodal)) != e.methods.end();
  if (!(requested || (e.methods.empty() && e.multimodal.configured()))) return "";
  if (!e.multimodal.model.empty()) return e.multimodal.model;
  const char* env = std::getenv("CLIPS_CHAT_MODEL");
  return env && *env ? env : "default";
}

}  // namespace

BenchReport run_bench(const BenchOptions& opts) {
  auto t0 = std::chrono::steady_clock::now();
  if (opts.shard_count < 1 || opts.shard < 1 || opts.shard > opts.shard_count)
    throw InputError(fmt::format("shard {}/{}: K must be between 1 and N", opts.shard, opts.shard_count));
  BenchReport rep;
  rep.loaded = std::make_shared<const data::Dataset>(data::Dataset::load(opts.dataset));
  // A stimuli.json that does not read fails every plan in `validate`: the run stops here too.
  if (!rep.loaded->stimuli_error().empty())
    throw InputError(rep.loaded->stimuli_error() + " (fix the file, or remove it: it is optional)");
  const data::Dataset& ds0 = *rep.loaded;
  check_selection(ds0, opts);
  rep.domain = ds0.pack().name();
  rep.dataset = opts.dataset;
  rep.fingerprint = dataset_fingerprint(opts.dataset);
  rep.started_utc = utc_now_iso8601();
  rep.seed = opts.experiment.seed;
  rep.assistance = assistance_set_choices().name(opts.experiment.all_assistance ? AssistanceSet::All
                                                                                   : AssistanceSet::Default);
  rep.methods_requested = opts.experiment.methods;
  rep.chat_model = multimodal_model(opts.experiment);
  const Selection all = select_plans(ds0, opts);
  if (all.plans.empty()) throw InputError("no plans to evaluate in " + opts.dataset);
  rep.selection = all.ids();
  rep.shards.count = opts.shard_count;
  rep.shards.present = {opts.shard};
  // A shard may hold no plan (more shards than plans): its files are then
  // written with no rows, and merging still accounts for it.
  const Selection mine = shard_part(all, rep.shards);
  const std::vector<const data::PlanRecord*>& todo = mine.plans;
  auto lm = opts.language_model ? opts.language_model : language::make_dataset_language_model(opts.lm, opts.lm_options, ds0);
  rep.lm = lm->name();
  // The embedded model loads its trained snapshot (or trains) on first use:
  // that is model loading, not a step of the first plan to hear an
  // instruction, so it happens before the plans start (their step times are
  // reported). Other backends are not called for it.
  if (rep.lm.find("embedded") != std::string::npos) {
    std::vector<std::string> problems;
    for (const data::PlanRecord* p : todo) problems.push_back(p->problem_id);
    language::warm_up_language_model(*lm, ds0, problems);
  }
  rep.speaker_rule = inference::to_string(opts.experiment.speaker_rule);
  rep.utterance_timing = inference::to_string(opts.experiment.utterance_timing);
  rep.qa_floor = assist::to_string(opts.experiment.qa_floor);
  rep.assistant_turns = inference::to_string(opts.experiment.assistant_turns);
  rep.plans.resize(todo.size());
  int jobs = opts.jobs > 0 ? opts.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  jobs = std::max(1, std::min<int>(jobs, static_cast<int>(todo.size())));
  // Cores the plan-level jobs leave idle refine each plan's hypotheses in
  // parallel instead (results do not depend on it).
  ExperimentOptions experiment = opts.experiment;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (experiment.inference_threads == 1 && cores / jobs > 1) experiment.inference_threads = cores / jobs;
  std::atomic<size_t> next{0};
  std::atomic<int> done{0};
  std::mutex mu;
  bool tty = opts.progress && isatty(STDERR_FILENO);
  auto worker = [&] {
    // Every worker shares ds0: its tasks are immutable once grounded, and each
    // problem is grounded once, by whichever worker needs it first.
    const data::Dataset& ds = ds0;
    for (;;) {
      size_t i = next++;
      if (i >= todo.size()) return;
      const auto& p = ds.plan(todo[i]->id);
      rep.plans[i] = evaluate_plan(ds, p, *lm, experiment);
      int d = ++done;
      if (opts.progress) {
        std::lock_guard<std::mutex> lock(mu);
        progress_line(d, static_cast<int>(todo.size()),
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), tty);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
  for (auto& t : pool) t.join();

  // Plans whose files did not load are reported as failed plans (with the
  // file's error), after the others.
  for (const data::BrokenPlan* b : mine.broken) {
    PlanOutcome bad;
    bad.plan_id = b->id;
    bad.error = "could not be loaded: " + b->error;
    rep.plans.push_back(std::move(bad));
  }
  summarise(rep);
  rep.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  rep.max_rss_kb = ru.ru_maxrss;
  return rep;
}

LatencyStats LatencyStats::of(std::vector<double> xs) {
  LatencyStats l;
  l.n = xs.size();
  if (xs.empty()) return l;
  std::sort(xs.begin(), xs.end());
  const auto at = [&](double q) { return xs[static_cast<size_t>(q * static_cast<double>(xs.size() - 1))]; };
  l.median = at(0.5);
  l.p95 = at(0.95);
  l.max = xs.back();
  return l;
}

BenchLatency bench_latency(const BenchReport& r) {
  BenchLatency out;
  std::vector<double> steps, work, starts, decisions, all_decisions;
  bool clips_ran = false;
  for (const auto& p : r.plans) {
    if (!p.error.empty()) continue;
    out.inference_threads = std::max(out.inference_threads, p.inference_threads);
    for (size_t t = 0; t < p.step_seconds.size(); ++t) {
      if (t == 0) {
        starts.push_back(p.step_seconds[t]);
        continue;
      }
      steps.push_back(p.step_seconds[t]);
      work.push_back(t < p.step_work_seconds.size() ? p.step_work_seconds[t] : p.step_seconds[t]);
    }
    for (double x : p.step_seconds) out.inference_seconds += x;
    for (const auto& m : p.methods) {
      auto it = std::find_if(out.method_seconds.begin(), out.method_seconds.end(),
                             [&](const auto& e) { return e.first == m.method; });
      if (it == out.method_seconds.end()) it = out.method_seconds.insert(out.method_seconds.end(), {m.method, 0.0});
      it->second += m.seconds;
      if (m.seconds > out.slowest_seconds) {
        out.slowest_seconds = m.seconds;
        out.slowest_plan = p.plan_id;
        out.slowest_method = m.method;
      }
      if (!m.error.empty()) continue;
      all_decisions.insert(all_decisions.end(), m.decision_seconds.begin(), m.decision_seconds.end());
      if (m.method == "clips") {
        clips_ran = true;
        decisions.insert(decisions.end(), m.decision_seconds.begin(), m.decision_seconds.end());
      }
    }
  }
  out.step = LatencyStats::of(steps);
  out.step_one_thread = LatencyStats::of(work);
  out.start = LatencyStats::of(starts);
  out.decision_method = clips_ran ? "clips" : "all";
  out.decision = LatencyStats::of(clips_ran ? decisions : all_decisions);
  return out;
}

void summarise(BenchReport& rep) {
  rep.failed_plans = 0;
  rep.failed_methods = 0;
  rep.summary.clear();
  std::vector<std::string> order;  // methods in order of first appearance
  for (auto& p : rep.plans) {
    if (!p.error.empty()) ++rep.failed_plans;
    for (auto& m : p.methods)
      if (!m.error.empty()) ++rep.failed_methods;
    for (auto& m : p.methods)
      if (std::find(order.begin(), order.end(), m.method) == order.end()) order.push_back(m.method);
  }
  for (auto& name : order) {
    MethodSummary s;
    s.method = name;
    std::map<std::string, std::vector<double>> xs;
    for (auto& p : rep.plans) {
      const MethodResult* m = p.find(name);
      if (!p.error.empty() || !m || !m->error.empty()) continue;  // failed plans and methods are not averaged
      if (m->p_true_goal) xs["p_true_goal"].push_back(*m->p_true_goal);
      xs["assist_precision"].push_back(m->precision);
      xs["assist_recall"].push_back(m->recall);
      if (m->has_relative) {  // ratios to CLIPS: only when it ran on the plan
        xs["rel_plan_length"].push_back(m->rel_plan_length);
        xs["rel_human_cost"].push_back(m->rel_human_cost);
      }
      xs["goal_success"].push_back(m->goal_success);
    }
    for (auto& [k, v] : xs) s.metrics[k] = mean_se(v);
    rep.summary.push_back(s);
  }
}

namespace {

// Explicit requests asked and done, per method and split ("" = all plans).
struct RequestCount {
  int asked = 0, done = 0;
};
std::map<std::string, std::map<std::string, RequestCount>> request_counts(const BenchReport& r) {
  std::map<std::string, std::map<std::string, RequestCount>> out;
  for (const auto& p : r.plans) {
    if (!p.error.empty() || p.requested.empty()) continue;
    for (const auto& m : p.methods) {
      if (!m.error.empty() || !m.request_done) continue;
      auto count = [&](const std::string& split) {
        RequestCount& c = out[m.method][split];
        ++c.asked;
        if (*m.request_done) ++c.done;
      };
      count("");
      if (!p.split.empty()) count(p.split);
    }
  }
  return out;
}

}  // namespace

std::string summary_json(const BenchReport& r) {
  nlohmann::ordered_json j;
  j["domain"] = r.domain;
  j["dataset"] = r.dataset;
  j["dataset_fingerprint"] = r.fingerprint;
  j["clips_version"] = r.clips_version;
  j["git_commit"] = r.git_commit.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.git_commit);
  j["date"] = r.started_utc;
  j["seed"] = r.seed;
  j["assistance"] = r.assistance;
  nlohmann::ordered_json ran = nlohmann::ordered_json::array();
  for (auto& s : r.summary) ran.push_back(s.method);
  j["methods_run"] = ran;
  j["methods_requested"] = r.methods_requested;  // [] = the domain's defaults
  j["plans"] = r.plans.size();
  j["failed_plans"] = r.failed_plans;
  j["failed_methods"] = r.failed_methods;
  j["lm"] = r.lm;
  j["speaker_rule"] = r.speaker_rule;
  j["utterance_timing"] = r.utterance_timing;
  j["qa_floor"] = r.qa_floor;
  j["assistant_turns"] = r.assistant_turns;
  j["wall_seconds"] = r.wall_seconds;
  j["max_rss_mb"] = static_cast<double>(r.max_rss_kb) / 1024.0;
  // Sharded runs and merges of them say which part of the sweep they hold;
  // an unsharded run's summary is as it always was.
  if (r.shards.count > 1)
    j["shards"] = {{"count", r.shards.count},
                   {"present", r.shards.present},
                   {"missing", r.shards.missing()},
                   {"partial", r.shards.partial()},
                   {"selection_plans", r.selection.size()}};
  nlohmann::ordered_json methods = nlohmann::ordered_json::object();
  const auto counts = request_counts(r);
  for (auto& s : r.summary) {
    nlohmann::ordered_json m = nlohmann::ordered_json::object();
    int n = 0;  // plans the method ran on without an error
    for (auto& p : r.plans)
      if (const MethodResult* mr = p.find(s.method); p.error.empty() && mr && mr->error.empty()) ++n;
    m["n"] = n;
    for (auto& name : kMetricNames) {
      auto it = s.metrics.find(name);
      if (it == s.metrics.end()) continue;
      m[name] = {{"mean", it->second.mean}, {"se", it->second.se}};
    }
    if (auto it = counts.find(s.method); it != counts.end()) {
      // Plans whose instruction explicitly asked the assistant for something
      // (instructions.tsv's `requested`), and how many of those it did.
      nlohmann::ordered_json req = nlohmann::ordered_json::object();
      for (const auto& [split, c] : it->second)
        req[split.empty() ? "all" : split] = {{"asked", c.asked}, {"done", c.done}};
      m["requests"] = req;
    }
    methods[s.method] = m;
  }
  j["methods"] = methods;
  // By split, by instruction category, and the calibration of the goal posteriors.
  j.update(breakdown_json(breakdown(r)));
  // Per-step latency (issue 43), in milliseconds.
  const BenchLatency lat = bench_latency(r);
  const auto stats = [](const LatencyStats& l, const char* count) {
    return nlohmann::ordered_json{{count, l.n}, {"median_ms", l.median * 1e3}, {"p95_ms", l.p95 * 1e3},
                                  {"max_ms", l.max * 1e3}};
  };
  nlohmann::ordered_json latency = nlohmann::ordered_json::object();
  latency["inference_threads"] = lat.inference_threads;
  latency["belief_step"] = stats(lat.step, "steps");
  latency["belief_step_one_thread"] = stats(lat.step_one_thread, "steps");
  latency["belief_start"] = stats(lat.start, "plans");
  latency["decision_method"] = lat.decision_method;
  latency["assistance_decision"] = stats(lat.decision, "decisions");
  nlohmann::ordered_json by_method = nlohmann::ordered_json::object();
  for (const auto& [m, sec] : lat.method_seconds) by_method[m] = sec;
  latency["seconds"] = {{"inference", lat.inference_seconds},
                        {"methods", by_method},
                        {"longest_run", {{"plan", lat.slowest_plan}, {"method", lat.slowest_method},
                                         {"seconds", lat.slowest_seconds}}}};
  j["latency"] = latency;
  return j.dump(2) + "\n";
}

// Columns after the first two (plan, method, which readers take by position)
// are read by name; `domain` was added last so no position moved.
std::string results_csv(const BenchReport& r) {
  std::string out = "plan,method,p_true_goal,assist_precision,assist_recall,plan_length,human_cost,plan_cost,"
                    "rel_plan_length,rel_human_cost,goal_success,seconds,options,goal_posterior,error,domain,requested,"
                    "request_done\n";
  // Six significant digits: fast plans take well under a millisecond.
  const auto secs = [](double v) { return fmt::format("{:.6g}", v); };
  for (auto& p : r.plans) {
    if (!p.error.empty()) {
      // plan, 10 empty metric fields, seconds, options, goal_posterior, error, domain, requested,
      // request_done: the header's 18 fields.
      out += p.plan_id + std::string(11, ',') + secs(p.seconds) + ",,," + csv_quote(p.error) + "," + r.domain + "," +
             (p.requested.empty() ? "" : csv_quote(p.requested)) + ",\n";
      continue;
    }
    for (auto& m : p.methods) {
      std::string opts, post;
      for (auto& [o, v] : m.options) opts += (opts.empty() ? "" : ";") + o + "=" + fmt::format("{:.4g}", v);
      for (size_t g = 0; g < m.goal_posterior.size(); ++g)
        post += (g ? ";" : "") + p.goals[g] + "=" + fmt::format("{:.4g}", m.goal_posterior[g]);
      auto relative = [&](double v) { return m.has_relative ? fmt::format("{:.6g}", v) : std::string(); };
      out += fmt::format("{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{},{:.6g},{},{},{},{},{},{},{}\n", p.plan_id,
                         m.method, m.p_true_goal ? fmt::format("{:.6g}", *m.p_true_goal) : "", m.precision, m.recall,
                         m.plan_length, m.human_cost, m.plan_cost, relative(m.rel_plan_length),
                         relative(m.rel_human_cost), m.goal_success, secs(m.seconds), csv_quote(opts), csv_quote(post),
                         m.error.empty() ? "" : csv_quote(m.error), r.domain,
                         p.requested.empty() ? "" : csv_quote(p.requested), m.request_done ? (*m.request_done ? "1" : "0") : "");
    }
  }
  return out;
}

std::string posteriors_csv(const BenchReport& r) {
  std::string out = "domain,plan,method,t,goal,probability\n";
  const auto rows = [&](const PlanOutcome& p, const MethodResult& m, size_t t, const std::vector<double>& post) {
    for (size_t g = 0; g < post.size() && g < p.goals.size(); ++g)
      out += fmt::format("{},{},{},{},{},{:.17g}\n", r.domain, p.plan_id, m.method, t, p.goals[g], post[g]);
  };
  for (auto& p : r.plans) {
    if (!p.error.empty()) continue;
    for (auto& m : p.methods) {
      if (!m.error.empty()) continue;
      if (!m.posterior_steps.empty()) {
        for (size_t t = 0; t < m.posterior_steps.size(); ++t) rows(p, m, t, m.posterior_steps[t]);
      } else if (!m.goal_posterior.empty()) {
        const size_t T = p.goal_posterior_steps.empty() ? 0 : p.goal_posterior_steps.size() - 1;
        rows(p, m, T, m.goal_posterior);
      }
    }
  }
  return out;
}

std::string results_table(const BenchReport& r, const std::string& paper_json_path) {
  nlohmann::json paper;
  if (std::ifstream in(paper_json_path); in) {
    try {
      paper = nlohmann::json::parse(in);
    } catch (...) {
    }
  }
  const nlohmann::json* ours_paper = paper_results_for(r, paper);
  std::vector<std::pair<std::string, std::string>> cols = {{"p_true_goal", "P(g_true)"},
                                                           {"assist_precision", "precision"},
                                                           {"assist_recall", "recall"},
                                                           {"rel_plan_length", "rel. length"},
                                                           {"rel_human_cost", "rel. human cost"}};
  std::string out = fmt::format("{} — {} plans, LM: {}, {:.1f} s wall, max RSS {:.0f} MiB\n", r.domain, r.plans.size(),
                                r.lm, r.wall_seconds, r.max_rss_kb / 1024.0);
  if (const std::string note = partial_note(r); !note.empty()) out += note + "\n";
  out += fmt::format("{:<26}", "method");
  for (auto& [k, label] : cols) out += fmt::format(" | {:^23}", label);
  out += "\n" + fmt::format("{:<26}", "");
  for (size_t i = 0; i < cols.size(); ++i)
    out += ours_paper ? fmt::format(" | {:^11} {:^11}", "ours", "paper") : fmt::format(" | {:^23}", "ours");
  out += "\n" + std::string(26 + cols.size() * 26, '-') + "\n";
  bool no_reference = false;  // relative metrics without a CLIPS run to compare with
  for (auto& s : r.summary) {
    out += fmt::format("{:<26}", s.method);
    for (auto& [k, label] : cols) {
      auto it = s.metrics.find(k);
      const bool relative = k.rfind("rel_", 0) == 0;
      std::string ours = it != s.metrics.end() ? fmt::format("{:.2f} ({:.2f})", it->second.mean, it->second.se)
                         : relative         ? "n/a"
                                            : "–";
      no_reference |= relative && it == s.metrics.end();
      if (!ours_paper) {
        out += fmt::format(" | {:^23}", ours);
        continue;
      }
      std::string theirs = "–";
      if (ours_paper->contains(s.method) && (*ours_paper)[s.method].contains(k)) {
        auto v = (*ours_paper)[s.method][k];
        theirs = fmt::format("{:.2f} ({:.2f})", v[0].get<double>(), v[1].get<double>());
      }
      out += fmt::format(" | {:^11} {:^11}", ours, theirs);
    }
    out += "\n";
  }
  // Where the paper reports a multimodal row for this domain, say why ours has none.
  if (paper_has_method(paper, r.domain, "multimodal") && !r.summary.empty()) {
    bool ran = false;
    for (auto& s : r.summary) ran |= s.method == baseline_choices().name(Baseline::Multimodal);
    if (!ran) out += "multimodal (GPT-4V-style)  | skipped: no chat endpoint configured (see --help)\n";
  }
  if (no_reference)
    out += "n/a: relative length and cost are ratios to CLIPS (offline Q_MDP) on the same plan; add clips to "
           "--methods\n";
  if (const BenchLatency lat = bench_latency(r); lat.step.n + lat.start.n + lat.decision.n > 0) {
    const auto ms = [](const LatencyStats& l) {
      return fmt::format("median {:.2f} ms, p95 {:.2f} ms, max {:.2f} ms", l.median * 1e3, l.p95 * 1e3, l.max * 1e3);
    };
    out += fmt::format("latency: belief step {} ({} steps, {} thread{} per plan)", ms(lat.step), lat.step.n,
                       lat.inference_threads, lat.inference_threads > 1 ? "s" : "");
    if (lat.inference_threads > 1) out += fmt::format("; on one thread {}", ms(lat.step_one_thread));
    out += fmt::format("\nlatency: first step at s_0 median {:.2f} ms, max {:.2f} ms ({} plans)\n", lat.start.median * 1e3,
                       lat.start.max * 1e3, lat.start.n);
    if (lat.decision.n > 0)
      out += fmt::format("latency: assistance decision ({}) {} ({} decisions)\n", lat.decision_method, ms(lat.decision),
                         lat.decision.n);
    // Summed over plans (threads overlap them), so a user sees which part of
    // the wall time to look at first.
    out += fmt::format("time: inference {:.1f} s", lat.inference_seconds);
    for (const auto& [m, sec] : lat.method_seconds) out += fmt::format(", {} {:.1f} s", m, sec);
    if (!lat.slowest_plan.empty())
      out += fmt::format(" (summed over plans; longest run: {} on {}, {:.1f} s)", lat.slowest_method, lat.slowest_plan,
                         lat.slowest_seconds);
    out += "\n";
  }
  if (r.failed_plans) {
    out += fmt::format("{} plan(s) failed:\n", r.failed_plans);
    for (auto& p : r.plans)
      if (!p.error.empty()) out += fmt::format("  {}: {}\n", p.plan_id, p.error);
  }
  // A method that failed on a plan is left out of its averages only.
  for (auto& p : r.plans)
    for (auto& m : p.methods)
      if (!m.error.empty()) out += fmt::format("{} failed on {}: {}\n", m.method, p.plan_id, m.error);
  out += breakdown_table(breakdown(r));
  if (const auto counts = request_counts(r); !counts.empty()) {
    out += "\nExplicit requests done (plans whose instruction asked the assistant for something; instructions.tsv):\n";
    for (const auto& s : r.summary) {
      auto it = counts.find(s.method);
      if (it == counts.end()) continue;
      std::string line = fmt::format("  {:<18}", s.method);
      for (const auto& [split, c] : it->second)
        line += fmt::format(" {} {}/{}", split.empty() ? "all" : split, c.done, c.asked);
      out += line + "\n";
    }
  }
  return out;
}

}  // namespace clips::eval
