#pragma once
// Loader for the paper's dataset layout, for any directory shaped like
//   <dir>/domain.pddl, problems/<P>.pddl, plans/{observed,completed}/<plan>.pddl
// plus, for Doors-Keys-Gems, utterances/{pragmatic,literal}/<plan>.txt and
// stimuli.json, and where the domain's pack takes goals from goal sets,
// goals/definitions/<label>.pddl and goals/sets/<P>.txt. The domain pack
// (domains/pack.hpp) is found from the domain's name or the folder's own
// pack.json; everything domain-specific below comes from it.
//
// Loading rejects, with an InputError naming the file (and line, or entry and
// field for stimuli.json): utterance files with other than one non-blank
// line; mDKG observed plans without exactly one `;` utterance; empty or
// non-UTF-8 utterances; repeated labels in a VH goal set; malformed or
// inconsistent stimuli.json entries (the file itself is optional).
// A bad file that belongs to one plan (its observed or completed plan, its
// utterance files, a missing problem file) does not stop the load: the plan is
// set aside with its error (broken_plans()), which is raised only when that
// plan is asked for, so every other plan stays usable.
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "domains/pack.hpp"
#include "pddl/plan.hpp"
#include "pddl/task.hpp"

namespace clips::data {

// What a caller bounds when a problem is grounded: the number of ground
// actions, and a wall-clock deadline (pddl::GroundingOptions).
struct GroundingLimits {
  int64_t max_ground_actions = pddl::GroundingOptions::kDefaultMaxGroundActions;
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  std::string deadline_label = "time limit";
  GroundingLimits() = default;
  GroundingLimits(int64_t max_actions) : max_ground_actions(max_actions) {}  // NOLINT: a size alone converts
  void apply(pddl::GroundingOptions& o) const {
    o.max_ground_actions = max_ground_actions;
    o.deadline = deadline;
    o.deadline_label = deadline_label;
  }
};

struct PlanRecord {
  std::string id;          // file stem, e.g. "2.1.keys" or "1.1.stew_chicken"
  std::string problem_id;  // e.g. "2", "10b", "demo0"
  int index = 0;           // plan index on that problem
  std::string tag;         // mDKG: "keys"/"doors"; VH: the true goal label
  bool evaluated = true;   // mDKG tutorial plans (demo*) are not evaluated
  pddl::PlanFile observed;
  pddl::PlanFile completed;
  std::optional<std::string> pragmatic_utterance;  // utterances/pragmatic (mDKG)
  std::optional<std::string> literal_utterance;    // utterances/literal (mDKG)
  // From the dataset's instructions.tsv, when it lists the plan: the half of
  // the data it belongs to ("dev": tuned on; "test": reported) and the kinds
  // of instruction it holds ("synonym", "joint", ...). Empty otherwise.
  std::string split;
  std::vector<std::string> categories;
  // From instructions.tsv's optional `requested` column: the ground atoms
  // (`(holding human can1)`, `(not (locked shed))`) that the instruction
  // explicitly asks the assistant to bring about, in the writer's reading;
  // empty when it asks nothing of the assistant. `clips bench` reports
  // whether each method's assistant did it.
  std::string requested;
};

using GoalSpec = domains::GoalSpec;

// A plan that could not be loaded, and why (the message names the file).
struct BrokenPlan {
  std::string id;     // file stem of its observed plan
  std::string error;  // the InputError's message
};

struct StimulusInfo {  // one entry of stimuli.json (mDKG)
  std::string name, type, utterance;
  int timesteps = 0, option_count = 0, goal = -1;
  std::vector<int> best_options;  // 1-based option numbers
};

class Dataset {
 public:
  // `require_plans = false` also accepts a folder without plans/observed/ (a
  // domain folder with problems only: `clips serve`, Session::open_dataset).
  static Dataset load(const std::string& dir, bool require_plans = true);
  // The domain, its pack, problems and goal sets only: no plan, utterance,
  // instructions.tsv or stimuli.json is read (`clips plan --problem`, whose
  // start-up time is most of a short search's).
  static Dataset load_problems(const std::string& dir);

  const std::string& dir() const { return dir_; }
  // What clips knows about the domain beyond its PDDL.
  const domains::Pack& pack() const { return *pack_; }
  const domains::PackPtr& pack_ptr() const { return pack_; }
  std::shared_ptr<const pddl::Domain> domain() const { return domain_; }
  const std::vector<PlanRecord>& plans() const { return plans_; }  // the plans that loaded
  const std::vector<BrokenPlan>& broken_plans() const { return broken_; }  // in file-name order
  // Throws InputError listing ids, or with the plan's own load error.
  const PlanRecord& plan(const std::string& id) const;

  // Grounded task of a problem (grounded once, then shared). Thread-safe: the
  // first caller for a problem grounds it while later callers for the same
  // problem wait; other problems load in parallel. A Dataset (and its tasks)
  // can be shared by any number of threads. For mDKG, throws
  // an InputError naming the problem file if an agent or door is not on the
  // grid, or a key or gem is neither on it nor held by an agent.
  std::shared_ptr<const pddl::Task> task(const std::string& problem_id) const;
  std::string problem_path(const std::string& problem_id) const;
  // The problems of problems/*.pddl (file stems), with or without plans, in
  // the plans' order (numeric id, letter suffix, then name).
  const std::vector<std::string>& problem_ids() const { return problem_ids_; }
  // The grounding limits (size, deadline) of tasks grounded after the call
  // (clips plan --max-ground-actions, --max-seconds).
  void set_grounding_limits(const GroundingLimits& l) { grounding_limits_ = l; }

  // The candidate goals of a plan's problem, in the paper's order, and the
  // index of the plan's true goal among them.
  std::vector<GoalSpec> candidate_goals(const PlanRecord& p) const;
  int true_goal_index(const PlanRecord& p) const;
  const std::map<std::string, std::string>& goal_definitions() const { return goal_defs_; }
  // Throws the InputError of a malformed stimuli.json (kept from the load).
  const std::optional<StimulusInfo> stimulus(const std::string& plan_id) const;
  const std::string& stimuli_error() const { return stimuli_error_; }

 private:
  enum class PlanFiles { required, optional, skipped };
  static Dataset load(const std::string& dir, PlanFiles plan_files);

  std::string dir_;
  domains::PackPtr pack_;
  std::shared_ptr<const pddl::Domain> domain_;
  std::vector<PlanRecord> plans_;
  std::vector<BrokenPlan> broken_;
  std::vector<std::string> problem_ids_;
  std::map<std::string, std::string> goal_defs_;                 // goal label -> condition text
  std::map<std::string, std::string> goal_def_paths_;            // goal label -> its goals/definitions file
  std::map<std::string, std::vector<std::string>> goal_sets_;   // problem -> labels
  std::map<std::string, StimulusInfo> stimuli_;
  std::string stimuli_error_;  // a malformed stimuli.json: raised by stimulus()
  GroundingLimits grounding_limits_;
  // Grounded tasks, one slot per problem, each with its own lock. Shared by
  // copies of the Dataset (the tasks are immutable).
  struct TaskSlot {
    std::mutex mutex;
    std::shared_ptr<const pddl::Task> task;
  };
  struct TaskTable {
    std::mutex mutex;  // guards `slots` only, never held while grounding
    std::map<std::string, std::shared_ptr<TaskSlot>> slots;
  };
  std::shared_ptr<TaskTable> tasks_ = std::make_shared<TaskTable>();
};

// The two list files the loader reads, parsed from their text (`path` names
// the file in errors). stimuli.json (the mDKG experiment's stimulus list):
// every entry checked against `plans` (see dataset.cpp), except entries
// naming a plan in `broken` (set aside at load), which are skipped. goals/sets/<P>.txt: one goal label per non-blank line,
// each defined in `goal_defs` and listed once.
std::map<std::string, StimulusInfo> parse_stimuli(const std::string& text, const std::string& path,
                                                  const std::vector<PlanRecord>& plans,
                                                  const std::vector<BrokenPlan>& broken = {});
std::vector<std::string> parse_goal_set(const std::string& text, const std::string& path,
                                        const std::map<std::string, std::string>& goal_defs);
// instructions.tsv: a header line "plan<TAB>split<TAB>categories" (and
// optionally "<TAB>requested"), then one line per plan: its id, "dev" or
// "test", comma-separated category names (lower-case words and hyphens) and,
// with the fourth column, the requested atoms (PlanRecord::requested). Sets each listed plan's split and
// categories; a plan listed twice, an unknown plan (one neither loaded nor
// set aside in `broken`), a bad split or category name is an InputError at
// path:line.
void apply_instruction_table(const std::string& text, const std::string& path, std::vector<PlanRecord>& plans,
                             const std::vector<BrokenPlan>& broken = {});
// An utterance given outside a plan file: non-empty, valid UTF-8; throws
// InputError at `loc` otherwise.
void check_utterance(const std::string& text, const SourceLoc& loc);
// A problem of `domain` grounded as its pack asks and checked by it (what
// Dataset::task does), for problems outside a dataset: the pack's task
// transformations applied (domains/task_transform.hpp; `domain` may be as
// parsed or already prepared). Loads the problem's :goal only when the pack
// takes its goal from there.
std::shared_ptr<const pddl::Task> ground_problem(const domains::Pack& pack,
                                                 std::shared_ptr<const pddl::Domain> domain,
                                                 const std::string& problem_path,
                                                 const GroundingLimits& limits = {});
// The same for a problem given as PDDL text; `source` names it in errors
// ("problem:3:5: ...").
std::shared_ptr<const pddl::Task> ground_problem_text(const domains::Pack& pack,
                                                      std::shared_ptr<const pddl::Domain> domain,
                                                      const std::string& problem_text, const std::string& source,
                                                      const GroundingLimits& limits = {});
// For a domain and problem given as text rather than as files. The pack of
// a domain: parsed from `pack_json` (errors name `source`) and checked
// against the domain, or, when it is empty, found by the domain's name (the
// data folder's packs, the compiled-in ones, else the generic pack).
domains::PackPtr text_pack(const pddl::Domain& domain, const std::string& pack_json, const std::string& source);
// The candidate goals of a problem by its pack's rule, when the pack takes
// them from the problem (objects or its :goal); a pack that takes them from
// goal sets (files of a folder) is refused, naming `source`.
std::vector<GoalSpec> text_problem_goals(const domains::Pack& pack, const pddl::Task& task, const std::string& source);
// The goal set goals/sets/<problem>.txt of a folder in the dataset layout,
// with each label's condition from goals/definitions/.
std::vector<GoalSpec> folder_goal_set(const std::string& dir, const std::string& problem_id);

}  // namespace clips::data
