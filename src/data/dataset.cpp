#include "data/dataset.hpp"
#include "data/goal_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "domains/builtin/packs.hpp"
#include "domains/task_transform.hpp"
#include "pddl/parser.hpp"
#include "util/utf8.hpp"

namespace fs = std::filesystem;

namespace clips::data {

namespace {

void check_utterance_text(const std::string& text, const SourceLoc& loc) {
  if (text.empty()) throw InputError(loc, "empty utterance (a ';' line needs the words spoken after it)");
  size_t bad = util::invalid_utf8_at(text);
  if (bad != std::string::npos) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02x", static_cast<unsigned char>(text[bad]));
    throw InputError(loc, "utterance is not valid UTF-8 (byte " + std::string(hex) + " at offset " +
                              std::to_string(bad) + " of the text)");
  }
}

// utterances/{pragmatic,literal}/<plan>.txt hold exactly one utterance: one
// non-blank line (surrounding whitespace stripped). Datasets with several
// utterances per plan keep them in the observed plan as `;` lines instead,
// so a second non-blank line is an error, not a continuation to drop silently.
std::string utterance_file(const std::string& path) {
  std::istringstream in(pddl::read_text_file(path));  // a regular file only
  std::string line, out;
  int line_no = 0, first = 0;
  while (std::getline(in, line)) {
    ++line_no;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    size_t a = line.find_first_not_of(" \t");
    if (a == std::string::npos) continue;
    if (first)
      throw InputError(SourceLoc{path, line_no, 1}, "an utterance file holds exactly one utterance on one line, "
                                                    "but line " + std::to_string(first) + " already held it");
    first = line_no;
    out = line.substr(a);
    check_utterance_text(out, SourceLoc{path, line_no, 1});
  }
  if (!first) throw InputError(path + " is empty (an utterance file holds one utterance on one line)");
  return out;
}

// Utterances of an observed plan: each must be non-empty, valid UTF-8 text,
// and no more than the pack allows (mDKG: one, spoken after the actions;
// there may be no actions, as in 15.1.doors). Inference from actions alone
// is a legitimate use, so the loader accepts a plan without an utterance. An
// observed plan with neither actions nor utterances gives nothing to infer
// from and is rejected.
void check_observed_plan(const domains::Pack& pack, const pddl::PlanFile& obs) {
  for (auto& u : obs.utterances) check_utterance_text(u.text, u.loc);
  pack.check_observed_plan(obs);
  if (obs.actions.empty() && obs.utterances.empty())
    throw InputError(SourceLoc{obs.path, 0, 0}, "observed plan is empty (no actions and no '; <utterance>' line)");
}

// The non-blank lines of a text, stripped, with their 1-based line numbers.
std::vector<std::pair<int, std::string>> lines_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::pair<int, std::string>> out;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    size_t a = line.find_first_not_of(" \t");
    if (a != std::string::npos) out.push_back({line_no, line.substr(a)});
  }
  return out;
}

// A JSON value as an error message shows it: numbers and strings as written
// (strings shortened), other values by their type.
std::string describe_json(const nlohmann::json& v) {
  if (v.is_number()) return v.dump();
  if (v.is_string()) {
    std::string t = v.dump();
    return "the string " + (t.size() > 40 ? t.substr(0, 37) + "...\"" : t);
  }
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  if (v.is_boolean()) return v.dump();
  return "null";
}

// Reads stimuli.json. Every field is checked, with errors naming the file,
// the entry (1-based, in file order), its plan and the field: integers must be
// integral numbers in range (1.0 is accepted; 1.5 and 1e30 are not), "goal" is
// [g] with g a 0-based gem index, "best_option" is [[o, ...]] with 1-based
// option numbers up to "option_count". Each entry must name a plan of the
// dataset, at most once, and agree with that plan's condition ("type" = the
// tag in its file name) and observed utterance.
}  // namespace

std::map<std::string, StimulusInfo> parse_stimuli(const std::string& text, const std::string& path,
                                                  const std::vector<PlanRecord>& plans,
                                                  const std::vector<BrokenPlan>& broken) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& ex) {
    throw InputError(SourceLoc{path, 0, 0}, std::string("malformed JSON: ") + ex.what());
  }
  if (!j.is_array()) throw InputError(SourceLoc{path, 0, 0}, "expected a JSON array of stimuli, got " + describe_json(j));
  constexpr long long kIntMax = std::numeric_limits<int>::max();
  std::map<std::string, StimulusInfo> out;
  std::map<std::string, size_t> entry_of;  // plan id -> 1-based entry
  for (size_t i = 0; i < j.size(); ++i) {
    const auto& o = j[i];
    std::string where = "entry " + std::to_string(i + 1);
    auto error = [&](const std::string& what) { return InputError(SourceLoc{path, 0, 0}, where + ": " + what); };
    auto field_error = [&](const char* f, const std::string& what) {
      return error(std::string("field \"") + f + "\": " + what);
    };
    if (!o.is_object()) throw error("expected an object, got " + describe_json(o));
    auto field = [&](const char* f) -> const nlohmann::json& {
      auto it = o.find(f);
      if (it == o.end()) throw error(std::string("field \"") + f + "\" is missing");
      return *it;
    };
    auto text = [&](const char* f) {
      const auto& v = field(f);
      if (!v.is_string()) throw field_error(f, "expected a string, got " + describe_json(v));
      return v.get<std::string>();
    };
    auto integer = [&](const char* f, const nlohmann::json& v, long long lo, long long hi) {
      long double x = 0;
      if (v.is_number_unsigned()) x = static_cast<long double>(v.get<unsigned long long>());
      else if (v.is_number_integer()) x = static_cast<long double>(v.get<long long>());
      else if (v.is_number_float()) x = v.get<double>();
      if (!v.is_number() || !std::isfinite(x) || x != std::floor(x))
        throw field_error(f, "expected an integer, got " + describe_json(v));
      if (x < lo || x > hi)
        throw field_error(f, "expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " +
                                 describe_json(v));
      return static_cast<int>(x);
    };
    auto one_element = [&](const char* f) -> const nlohmann::json& {
      const auto& v = field(f);
      if (!v.is_array() || v.size() != 1)
        throw field_error(f, "expected an array of one element, got " +
                                 (v.is_array() ? "an array of " + std::to_string(v.size()) : describe_json(v)));
      return v[0];
    };

    StimulusInfo s;
    s.name = text("name");
    where += " (plan " + s.name + ")";
    auto plan = std::find_if(plans.begin(), plans.end(), [&](const PlanRecord& p) { return p.id == s.name; });
    if (plan == plans.end()) {
      // A plan that failed to load has its own error; its entry cannot be checked.
      if (std::any_of(broken.begin(), broken.end(), [&](const BrokenPlan& b) { return b.id == s.name; })) continue;
      throw error("no such plan in plans/observed/");
    }
    if (auto [it, fresh] = entry_of.emplace(s.name, i + 1); !fresh)
      throw error("a second entry for this plan (the first is entry " + std::to_string(it->second) + ")");
    s.type = text("type");
    s.utterance = text("utterance");
    s.timesteps = integer("timesteps", field("timesteps"), 0, kIntMax);
    s.option_count = integer("option_count", field("option_count"), 1, kIntMax);
    s.goal = integer("goal", one_element("goal"), 0, kIntMax);
    const auto& best = one_element("best_option");
    if (!best.is_array()) throw field_error("best_option", "expected [[o, ...]], got [" + describe_json(best) + "]");
    for (const auto& v : best) s.best_options.push_back(integer("best_option", v, 1, s.option_count));
    {
      if (s.type != plan->tag)
        throw field_error("type", "\"" + s.type + "\" differs from the plan's condition \"" + plan->tag + "\"");
      // The loader has checked that the observed plan holds at most one utterance.
      if (plan->observed.utterances.empty())
        throw field_error("utterance", "\"" + s.utterance + "\" is given, but the observed plan has no '; <utterance>' line");
      const auto& u = plan->observed.utterances.front();
      if (s.utterance != u.text)
        throw field_error("utterance", "\"" + s.utterance + "\" differs from the observed plan's utterance \"" +
                                           u.text + "\" (" + u.loc.str() + ")");
    }
    out[s.name] = std::move(s);
  }
  return out;
}

namespace {

bool goal_label_is_file_name(const std::string& label) {
  return !label.empty() && label[0] != '.' && label.find_first_of("/\\") == std::string::npos;
}

}  // namespace

std::vector<std::string> parse_goal_set(const std::string& text, const std::string& path,
                                        const std::map<std::string, std::string>& goal_defs) {
  std::vector<std::string> labels;
  std::map<std::string, int> seen;  // label -> line
  for (auto& [line_no, label] : lines_of(text)) {
    const SourceLoc loc{path, line_no, 1};
    // A label names its file goals/definitions/<label>.pddl and is written
    // into every JSON output: a plain file name in UTF-8 (its bytes are not
    // echoed when they are not UTF-8).
    if (const std::string bad = util::utf8_problem(label); !bad.empty())
      throw InputError(loc, "goal label is " + bad);
    if (!goal_label_is_file_name(label))
      throw InputError(loc, "goal label '" + label + "' must be a file name: no '/' or '\\', no leading '.'");
    if (!goal_defs.count(label))
      throw InputError(loc, "goal '" + label + "' has no file goals/definitions/" + label + ".pddl");
    // A repeated label would be a second, identical hypothesis sharing its probability.
    if (auto [it, fresh] = seen.emplace(label, line_no); !fresh)
      throw InputError(loc, "goal '" + label + "' is listed twice (also at line " + std::to_string(it->second) + ")");
    labels.push_back(label);
  }
  return labels;
}

namespace {

// Sort key: numeric map id, its letter suffix, then plan index.
struct PlanKey {
  int num;
  std::string suffix;
  int index;
  std::string name;
  bool operator<(const PlanKey& o) const {
    return std::tie(num, suffix, index, name) < std::tie(o.num, o.suffix, o.index, o.name);
  }
};

// CLIPS_DEBUG_LOAD=1: one stderr line per dataset load and per grounded
// problem, to check that parallel commands load and ground once.
bool debug_load() {
  static const bool on = [] {
    const char* v = std::getenv("CLIPS_DEBUG_LOAD");
    return v && *v && std::string(v) != "0";
  }();
  return on;
}

}  // namespace

void check_utterance(const std::string& text, const SourceLoc& loc) { check_utterance_text(text, loc); }

std::shared_ptr<const pddl::Task> ground_problem(const domains::Pack& pack,
                                                 std::shared_ptr<const pddl::Domain> domain,
                                                 const std::string& problem_path, const GroundingLimits& limits) {
  const bool with_goal = pack.spec().goals.source == domains::GoalSource::ProblemGoal;
  // A domain as parsed (not through load_domain_with_pack) gets the pack's additions here.
  domain = domains::prepare_domain(pack.spec(), std::move(domain));
  auto prob = std::make_shared<pddl::Problem>(pddl::load_problem(*domain, problem_path, with_goal));
  domains::prepare_problem(pack.spec(), *domain, *prob);
  pddl::GroundingOptions go = pack.spec().grounding;
  limits.apply(go);
  auto t = std::make_shared<const pddl::Task>(std::move(domain), std::move(prob), go);
  pack.check_problem(*t, problem_path);
  return t;
}

std::shared_ptr<const pddl::Task> ground_problem_text(const domains::Pack& pack,
                                                      std::shared_ptr<const pddl::Domain> domain,
                                                      const std::string& problem_text, const std::string& source,
                                                      const GroundingLimits& limits) {
  const bool with_goal = pack.spec().goals.source == domains::GoalSource::ProblemGoal;
  domain = domains::prepare_domain(pack.spec(), std::move(domain));
  auto prob = std::make_shared<pddl::Problem>(pddl::parse_problem(*domain, problem_text, source, with_goal));
  domains::prepare_problem(pack.spec(), *domain, *prob);
  pddl::GroundingOptions go = pack.spec().grounding;
  limits.apply(go);
  auto t = std::make_shared<const pddl::Task>(std::move(domain), std::move(prob), go);
  pack.check_problem(*t, source);
  return t;
}

domains::PackPtr text_pack(const pddl::Domain& domain, const std::string& pack_json, const std::string& source) {
  if (pack_json.find_first_not_of(" \t\r\n") == std::string::npos) {
    // Looked up by name in the data folder: a name must not walk out of it.
    if (domain.name.empty() || domain.name.find_first_of("/\\") != std::string::npos || domain.name[0] == '.')
      throw InputError("domain name '" + domain.name + "' cannot name a pack (no '/', '\\' or leading '.')");
    return domains::find_pack(domain);
  }
  return domains::pack_for_domain(domains::parse_pack_spec(pack_json, source), domain);
}

std::vector<GoalSpec> text_problem_goals(const domains::Pack& pack, const pddl::Task& task, const std::string& source) {
  if (pack.spec().goals.source == domains::GoalSource::GoalSets)
    throw InputError(source + ": pack " + pack.name() +
                     " takes its candidate goals from goal sets (goals/sets/<problem>.txt of a folder); give the "
                     "candidate goals, or a problem of the folder");
  return pack.problem_goals(task, source);
}

std::vector<GoalSpec> folder_goal_set(const std::string& dir_in, const std::string& problem_id) {
  const fs::path dir(dir_in), defs = dir / "goals" / "definitions";
  const fs::path set = dir / "goals" / "sets" / (problem_id + ".txt");
  if (!fs::exists(set)) throw InputError("no goal set " + set.string() + " for problem " + problem_id);
  std::map<std::string, std::string> texts;
  std::vector<GoalSpec> out;
  const std::string text = pddl::read_text_file(set.string());
  // Read only the definitions the set names.
  for (auto& [line_no, label] : lines_of(text)) {
    if (!goal_label_is_file_name(label)) continue;  // refused by parse_goal_set: nothing read outside definitions/
    const fs::path def = defs / (label + ".pddl");
    if (fs::exists(def)) texts[label] = pddl::read_text_file(def.string());
  }
  for (const auto& label : parse_goal_set(text, set.string(), texts))
    out.push_back({label, texts.at(label), (defs / (label + ".pddl")).string()});
  return out;
}

Dataset Dataset::load(const std::string& dir, bool require_plans) {
  return load(dir, require_plans ? PlanFiles::required : PlanFiles::optional);
}

Dataset Dataset::load_problems(const std::string& dir) { return load(dir, PlanFiles::skipped); }

Dataset Dataset::load(const std::string& dir_in, PlanFiles plan_files_wanted) {
  if (debug_load()) std::fprintf(stderr, "dataset: loading %s\n", dir_in.c_str());
  Dataset ds;
  ds.dir_ = dir_in;
  fs::path dir(dir_in);
  if (!fs::is_directory(dir))
    throw InputError("dataset directory '" + dir_in + (fs::exists(dir) ? "' is not a directory" : "' does not exist"));
  fs::path dom = dir / "domain.pddl";
  if (!fs::exists(dom)) throw InputError("dataset directory '" + dir_in + "' has no domain.pddl");
  auto [domain, pack] = domains::load_domain_with_pack(dom.string(), dir_in);
  ds.domain_ = std::move(domain);
  ds.pack_ = std::move(pack);

  fs::path obs_dir = dir / "plans" / "observed";
  fs::path comp_dir = dir / "plans" / "completed";
  const bool has_plans = plan_files_wanted != PlanFiles::skipped && fs::is_directory(obs_dir);
  if (!has_plans && plan_files_wanted == PlanFiles::required) throw InputError("dataset directory '" + dir_in + "' has no plans/observed/");
  // Compiled once: compiling a std::regex writes libstdc++'s shared
  // ctype<char>::narrow cache (GCC PR 77704), a race when datasets load on
  // several threads at once; matching only reads.
  static const std::regex eval_re(R"(^(\d+)(\w?)\.(\d+)\.(.+)$)");
  static const std::regex any_re(R"(^([A-Za-z0-9_]+)\.(\d+)\.(.+)$)");
  static const std::regex problem_re(R"(^(\d{1,9})([A-Za-z]?)$)");
  std::vector<std::pair<PlanKey, PlanRecord>> recs;
  // Plan files in name order, so broken_plans() and the load are deterministic.
  std::vector<fs::path> plan_files;
  if (has_plans)
    for (auto& e : fs::directory_iterator(obs_dir))
      if (e.path().extension() == ".pddl") plan_files.push_back(e.path());
  std::sort(plan_files.begin(), plan_files.end());
  for (const fs::path& path : plan_files) try {
    const fs::directory_entry e(path);
    std::string stem = e.path().stem().string();
    std::smatch m;
    PlanRecord r;
    r.id = stem;
    PlanKey key{1 << 30, "", 0, stem};
    if (std::regex_match(stem, m, eval_re)) {
      key = PlanKey{std::stoi(m[1]), m[2], std::stoi(m[3]), stem};
      r.problem_id = m[1].str() + m[2].str();
      r.index = std::stoi(m[3]);
      r.tag = m[4];
    } else if (std::regex_match(stem, m, any_re)) {
      r.problem_id = m[1];
      r.index = std::stoi(m[2]);
      r.tag = m[3];
      // The reference evaluates only "<digits><letter?>.<i>.<tag>" names, which
      // leaves out the mDKG tutorial plans demo0..2; other names (such as our
      // own examples) are evaluated, tutorials are recognised by their prefix.
      r.evaluated = r.problem_id.rfind("demo", 0) != 0;
    } else {
      throw InputError(SourceLoc{e.path().string(), 0, 0}, "plan file name must look like <problem>.<index>.<tag>.pddl");
    }
    r.observed = pddl::load_plan(e.path().string());
    check_observed_plan(*ds.pack_, r.observed);
    fs::path cp = comp_dir / e.path().filename();
    if (!fs::exists(cp)) throw InputError(SourceLoc{cp.string(), 0, 0}, "missing completed plan for " + stem);
    r.completed = pddl::load_plan(cp.string());
    fs::path prag = dir / "utterances" / "pragmatic" / (stem + ".txt");
    fs::path lit = dir / "utterances" / "literal" / (stem + ".txt");
    if (fs::exists(prag)) r.pragmatic_utterance = utterance_file(prag.string());
    if (fs::exists(lit)) r.literal_utterance = utterance_file(lit.string());
    if (!fs::exists(dir / "problems" / (r.problem_id + ".pddl")))
      throw InputError(SourceLoc{e.path().string(), 0, 0}, "no problem file problems/" + r.problem_id + ".pddl for plan " + stem);
    recs.push_back({key, std::move(r)});
  } catch (const InputError& err) {
    // This plan's files only: set it aside, the others stay usable.
    ds.broken_.push_back({path.stem().string(), err.what()});
  }
  std::sort(recs.begin(), recs.end(), [](auto& a, auto& b) { return a.first < b.first; });
  for (auto& [k, r] : recs) ds.plans_.push_back(std::move(r));
  {
    // Every problem file, in the plans' order.
    std::vector<PlanKey> keys;
    std::error_code ec;
    for (auto& e : fs::directory_iterator(dir / "problems", ec)) {
      if (e.path().extension() != ".pddl") continue;
      const std::string stem = e.path().stem().string();
      std::smatch m;
      if (std::regex_match(stem, m, problem_re)) keys.push_back({std::stoi(m[1]), m[2], 0, stem});
      else keys.push_back({1 << 30, "", 0, stem});
    }
    std::sort(keys.begin(), keys.end());
    for (auto& k : keys) ds.problem_ids_.push_back(k.name);
  }

  if (ds.pack_->spec().goals.source == domains::GoalSource::GoalSets) {
    fs::path defs = dir / "goals" / "definitions";
    fs::path sets = dir / "goals" / "sets";
    if (!fs::is_directory(defs) || !fs::is_directory(sets))
      throw InputError("dataset '" + dir_in + "' needs goals/definitions/ and goals/sets/ (the " +
                       ds.pack_->name() + " pack takes its candidate goals from goal sets)");
    for (auto& e : fs::directory_iterator(defs))
      if (e.path().extension() == ".pddl") {
        ds.goal_defs_[e.path().stem().string()] = pddl::read_text_file(e.path().string());
        ds.goal_def_paths_[e.path().stem().string()] = e.path().string();
      }
    for (auto& e : fs::directory_iterator(sets))
      if (e.path().extension() == ".txt") {
        const std::string path = e.path().string();
        ds.goal_sets_[e.path().stem().string()] = parse_goal_set(pddl::read_text_file(path), path, ds.goal_defs_);
      }
  }
  if (plan_files_wanted == PlanFiles::skipped) return ds;
  if (fs::path table = dir / "instructions.tsv"; fs::exists(table))
    apply_instruction_table(pddl::read_text_file(table.string()), table.string(), ds.plans_, ds.broken_);
  // stimuli.json (Doors-Keys-Gems) is optional: only `validate` reads it, to
  // cross-check the plans against it; the tutorial plans demo* have no entry,
  // and copies of the dataset with reworded utterances drop the file. When it
  // is present, it is checked in full (load_stimuli).
  fs::path stim = dir / "stimuli.json";
  // A bad stimuli.json concerns `validate` only: its error is kept for it.
  if (fs::exists(stim)) try {
      ds.stimuli_ = parse_stimuli(pddl::read_text_file(stim.string()), stim.string(), ds.plans_, ds.broken_);
    } catch (const InputError& err) {
      ds.stimuli_error_ = err.what();
    }
  return ds;
}

void apply_instruction_table(const std::string& text, const std::string& path, std::vector<PlanRecord>& plans,
                             const std::vector<BrokenPlan>& broken) {
  std::map<std::string, PlanRecord*> by_id;
  for (auto& p : plans) by_id[p.id] = &p;
  std::set<std::string> seen;
  auto word = [](const std::string& w) {
    return !w.empty() && std::all_of(w.begin(), w.end(), [](unsigned char c) {
      return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
    });
  };
  int line_no = 0;
  bool header = false;
  size_t columns = 3;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    start = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) {
      if (end == text.size()) break;
      continue;
    }
    std::vector<std::string> cols;
    for (size_t a = 0;;) {
      const size_t b = line.find('\t', a);
      cols.push_back(line.substr(a, b == std::string::npos ? std::string::npos : b - a));
      if (b == std::string::npos) break;
      a = b + 1;
    }
    const SourceLoc loc{path, line_no, 1};
    if (!header) {
      if ((cols.size() != 3 && cols.size() != 4) || cols[0] != "plan" || cols[1] != "split" || cols[2] != "categories" ||
          (cols.size() == 4 && cols[3] != "requested"))
        throw InputError(loc, "expected the header line \"plan<TAB>split<TAB>categories\" (optionally with "
                              "\"<TAB>requested\")");
      columns = cols.size();
      header = true;
      continue;
    }
    if (cols.size() != columns)
      throw InputError(loc, "expected " + std::to_string(columns) + " tab-separated columns, found " +
                                std::to_string(cols.size()));
    const std::string& id = cols[0];
    if (!seen.insert(id).second) throw InputError(loc, "plan " + id + " is listed twice");
    if (cols[1] != "dev" && cols[1] != "test")
      throw InputError(loc, "split '" + cols[1] + "' of plan " + id + " must be dev or test");
    std::vector<std::string> cats;
    for (size_t a = 0;;) {
      const size_t b = cols[2].find(',', a);
      std::string c = cols[2].substr(a, b == std::string::npos ? std::string::npos : b - a);
      while (!c.empty() && c.front() == ' ') c.erase(c.begin());
      while (!c.empty() && c.back() == ' ') c.pop_back();
      if (!word(c))
        throw InputError(loc, "category '" + c + "' of plan " + id + " must be lower-case letters, digits and hyphens");
      if (std::find(cats.begin(), cats.end(), c) == cats.end()) cats.push_back(c);
      if (b == std::string::npos) break;
      a = b + 1;
    }
    auto it = by_id.find(id);
    if (it == by_id.end()) {
      if (std::any_of(broken.begin(), broken.end(), [&](const BrokenPlan& b) { return b.id == id; })) continue;
      throw InputError(loc, "no plan " + id + " in plans/observed/");
    }
    it->second->split = cols[1];
    it->second->categories = std::move(cats);
    if (columns == 4) {
      std::string req = cols[3];
      while (!req.empty() && req.front() == ' ') req.erase(req.begin());
      while (!req.empty() && req.back() == ' ') req.pop_back();
      if (!req.empty() && (req.front() != '(' || req.back() != ')'))
        throw InputError(loc, "requested atoms of plan " + id + " must be ground atoms in parentheses, as "
                              "\"(holding human can1) (not (locked shed))\", not '" + req + "'");
      it->second->requested = std::move(req);
    }
  }
  if (!header) throw InputError(SourceLoc{path, 1, 1}, "empty file: expected the header line \"plan<TAB>split<TAB>categories\"");
}

const PlanRecord& Dataset::plan(const std::string& id) const {
  for (auto& p : plans_)
    if (p.id == id) return p;
  for (auto& b : broken_)
    if (b.id == id) throw InputError("plan " + id + " could not be loaded: " + b.error);
  // Accept a unique prefix such as "1.1" for a plan "1.1.<tag>".
  const PlanRecord* found = nullptr;
  for (auto& p : plans_)
    if (p.id.rfind(id + ".", 0) == 0) {
      if (found) throw InputError("plan id '" + id + "' is ambiguous");
      found = &p;
    }
  if (found) return *found;
  for (auto& b : broken_)
    if (b.id.rfind(id + ".", 0) == 0) throw InputError("plan " + b.id + " could not be loaded: " + b.error);
  std::string known;
  for (auto& p : plans_) known += (known.empty() ? "" : ", ") + p.id;
  throw InputError("no plan '" + id + "' in " + dir_ + " (known: " + known + ")");
}

std::string Dataset::problem_path(const std::string& problem_id) const {
  return (fs::path(dir_) / "problems" / (problem_id + ".pddl")).string();
}

std::shared_ptr<const pddl::Task> Dataset::task(const std::string& problem_id) const {
  std::shared_ptr<TaskSlot> slot;
  {
    std::lock_guard<std::mutex> lock(tasks_->mutex);
    auto& s = tasks_->slots[problem_id];
    if (!s) s = std::make_shared<TaskSlot>();
    slot = s;
  }
  std::lock_guard<std::mutex> lock(slot->mutex);
  if (slot->task) return slot->task;
  // A failure leaves the slot empty: the next caller tries again (and fails
  // with the same error).
  if (debug_load()) std::fprintf(stderr, "dataset: grounding problem %s\n", problem_id.c_str());
  auto t = ground_problem(*pack_, domain_, problem_path(problem_id), grounding_limits_);
  // A candidate goal the data defines (goal sets, the problem's :goal) that
  // no state can satisfy is a mistake: refused here, before inference plans
  // for the impossible.
  std::vector<GoalSpec> defined;
  if (pack_->spec().goals.source == domains::GoalSource::GoalSets) {
    if (auto set = goal_sets_.find(problem_id); set != goal_sets_.end())
      for (const auto& l : set->second) defined.push_back({l, goal_defs_.at(l), goal_def_paths_.at(l)});
  } else if (pack_->spec().goals.source == domains::GoalSource::ProblemGoal) {
    defined = pack_->problem_goals(*t, problem_path(problem_id));
  }
  const pddl::State s0 = t->initial_state();
  for (const GoalSpec& g : defined) {
    const std::string why = why_goal_never_holds(*t, t->compile_text(g.condition, g.source), s0);
    if (!why.empty())
      throw InputError(SourceLoc{g.source, 0, 0}, "goal '" + g.label + "' can never hold in problem " + problem_id +
                                                      ": " + why);
  }
  slot->task = t;
  return t;
}

std::vector<GoalSpec> Dataset::candidate_goals(const PlanRecord& p) const {
  std::vector<GoalSpec> out;
  if (pack_->spec().goals.source == domains::GoalSource::GoalSets) {
    auto it = goal_sets_.find(p.problem_id);
    if (it == goal_sets_.end()) throw InputError("no goal set goals/sets/" + p.problem_id + ".txt for plan " + p.id);
    for (auto& l : it->second) out.push_back({l, goal_defs_.at(l), goal_def_paths_.at(l)});
    return out;
  }
  return pack_->problem_goals(*task(p.problem_id), problem_path(p.problem_id));
}

int Dataset::true_goal_index(const PlanRecord& p) const {
  return pack_->true_goal_index(*task(p.problem_id), candidate_goals(p), p.tag, p.observed, p.completed);
}

const std::optional<StimulusInfo> Dataset::stimulus(const std::string& plan_id) const {
  if (!stimuli_error_.empty()) throw InputError(stimuli_error_);
  auto it = stimuli_.find(plan_id);
  if (it == stimuli_.end()) return std::nullopt;
  return it->second;
}

}  // namespace clips::data
