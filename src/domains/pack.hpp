#pragma once
// A domain pack: everything clips needs to know about a planning domain that
// its PDDL does not say. Who the principal and the assistant are, where the
// candidate goals come from and which one a plan pursued, the cost profiles,
// the heuristic and temperature prior of the human model, the command
// language, the literal listener, what counts as an assistance option, how a
// state is shown. The rest of clips asks the pack and never which domain it
// is.
//
// Most of a pack is data (PackSpec), read from a JSON file (pack.json; every
// field is documented in docs/domains.md). A pack may also carry code for what
// data cannot say (Doors-Keys-Gems: its grid heuristics and map checks): such
// packs subclass Pack and are named in the file by "code". Packs are
// immutable once built and safe to share between threads.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "heuristics/heuristic.hpp"
#include "language/commands/command.hpp"
#include "language/commands/fewshot.hpp"
#include "language/commands/language_config.hpp"
#include "language/commands/salient.hpp"
#include "model/spec.hpp"
#include "pddl/plan.hpp"
#include "pddl/task.hpp"
#include "util/rng.hpp"

namespace clips::domains {

// One candidate goal: a label and a PDDL condition.
struct GoalSpec {
  std::string label;      // e.g. "gem2" or "set_table1"
  std::string condition;  // e.g. "(has human gem2)"
  std::string source;     // the file `condition` was read from ("" when built in code), for error locations
};

// Who helps whom.
struct Roles {
  std::string principal = "human";  // the speaker, whose goal is inferred
  std::string assistant = "robot";  // the agent clips plays
  std::string noop_action = "wait";  // what an agent does when it does nothing
  int horizon = 100;                 // assistance episodes stop after this many steps
  // The principal's no-op cost in the assistance value (the true profile's
  // no-op cost in mDKG, 1 elsewhere).
  double noop_cost = 1.0;
  // The principal's simulated moves also take the k-th completed-plan action
  // when it is legal, even off the completed trajectory (VirtualHome).
  bool principal_follows_completed_plan = false;
};

// Where a problem's candidate goals come from.
enum class GoalSource {
  GoalSets,     // goals/sets/<problem>.txt lists labels, goals/definitions/<label>.pddl the conditions
  Objects,      // one goal per object of a type, from a condition template
  ProblemGoal,  // the problem's own :goal, as the only candidate
};
// How a plan's true goal is identified.
enum class TrueGoalRule {
  PlanTag,          // the plan file's tag (<problem>.<index>.<tag>.pddl) is the goal's label
  CompletionReaches,// the one candidate that holds at the end of the completed plan
  LastActionObject, // the object named by the completed plan's last action
};
struct GoalRule {
  GoalSource source = GoalSource::ProblemGoal;
  std::string object_type;  // Objects: e.g. "gem"
  std::string condition;    // Objects: e.g. "(has human {})", {} is the object's name
  TrueGoalRule true_goal = TrueGoalRule::CompletionReaches;
};

// Candidate cost profiles of the plans with one tag ("" = every other plan).
struct ProfileRule {
  std::string tag;
  std::vector<model::CostProfile> profiles;
  int true_index = 0;  // which profile the plans were made with
};
struct ProfileSet {
  std::vector<model::CostProfile> profiles;
  int true_index = 0;
};

// An assistant action that commits it to one option, for the precision and
// recall of assistance: `action` by the assistant, naming `object_arg`
// (1-based), if that object is of `object_type` ("" any) and the plan has
// `tag` ("" any).
struct OptionRule {
  std::string action;
  int object_arg = 2;
  std::string object_type;
  std::string tag;
};

// How the CLIPS speaker model rolls the policy forward to find what the
// speaker would say (spec 7.2; VH spec 6.1).
struct RolloutSettings {
  enum class Kind { Greedy, WeightedAStar };
  Kind kind = Kind::Greedy;
  // WeightedAStar: this flag predicate is set on the speaker first (VH
  // "nograb": the rest of the work is left to the listener).
  std::string speaker_flag;
};

struct InferenceSettings {
  // Of the human model's policies. h_FF: informative, not admissible (h_max
  // values most actions alike, which leaves the actions no evidence).
  std::string heuristic = "hff";
  bool search = true;              // false: V = -h_g with no search (VH)
  double temperature_shape = 0.5;  // inverse-gamma prior on the Boltzmann temperature
  double temperature_scale = 1.0;
  RolloutSettings rollout;
};

struct LiteralSettings {
  bool enabled = true;
  double temperature = 1.0;
  // The literal-listener methods a bench runs by default: "literal" (one
  // variant) or "literal_efficient" and "literal_naive".
  std::vector<std::string> methods = {"literal"};
  // The heuristic of the listener's own planning towards a command's goal.
  std::string planning_heuristic = "lmcut";
  // Types that name lifted variables (?key1, ?door2): an object is named by
  // the first of these it belongs to; empty: by its declared type.
  std::vector<std::string> variable_types;
};

// Where the few-shot command -> utterance examples come from.
struct FewShotSource {
  // A TSV file (fewshot.hpp format), absolute or relative to the pack file;
  // empty: the shared data/language/fewshot-examples.tsv.
  std::string file;
  // The examples' "domain" column (default: the pack's name).
  std::string domain;
  // Prompt orders (TSV indices); empty: prompt-orders.json of the shared
  // file, or the file's order for a pack's own file.
  std::vector<int> pragmatic_order, literal_order;
};

enum class SceneKind { Text, Grid, Cards };

struct PackSpec {
  std::string name;         // the PDDL domain name the pack is for
  // Hand-written corpora (files in data/language/) the embedded language
  // model trains on; empty: a corpus generated from the domain's PDDL names
  // and command language (language/lm/domain_corpus.hpp).
  std::vector<std::string> embedded_corpus;
  std::string code;         // built-in code behind the pack ("" none)
  std::string source;       // the file it was read from ("" built in)
  pddl::GroundingOptions grounding;
  Roles roles;
  GoalRule goals;
  std::vector<ProfileRule> cost_profiles;  // empty: unit costs
  // What `clips plan` uses without --costs ("": the domain's own action costs
  // if it declares (total-cost), else unit).
  std::string default_cost_profile;
  InferenceSettings inference;
  commands::LanguageConfig language;
  FewShotSource fewshot;
  LiteralSettings literal;
  std::vector<OptionRule> options;  // empty: every salient action of the assistant, on its focal object
  // At most this many utterances per observed plan (0: any).
  int max_utterances_per_plan = 0;
  // The plan tags a plan may have, when they mean something (mDKG: keys, doors).
  std::vector<std::string> plan_tags;
  SceneKind scene = SceneKind::Text;
  // Fills of a cards scene by type (an object's name without its trailing
  // digits: "plate" for "plate3") as "#rrggbb"; types not listed get a
  // pastel from a hash of the type (items) or grey (fixtures).
  std::map<std::string, std::string> scene_colours;
  std::string rules_text;  // the world's rules in English, for the multimodal LLM baseline
};

// A task compiled to plain STRIPS for an outside planner (e.g. Fast Downward).
struct StripsExport {
  std::string domain;    // PDDL text of the STRIPS domain
  std::string problem;   // PDDL text of the STRIPS problem
  int cost_scale = 1;    // exported cost = original cost * cost_scale
  std::string goal;      // the goal as exported, e.g. "(and (has human gem2))"
  // Exported action name -> original ground action ("" for an action the
  // export adds), when the names do not say it (the generic export; mDKG's
  // names map back by domains::to_original_action).
  std::map<std::string, std::string> original_actions;
};

// What `clips generate` asks a pack for: a random problem of this size with
// these many objects of each kind the pack knows (mDKG: "gem", "key", "door").
struct GenerateParams {
  int width = 9, height = 9;
  std::map<std::string, int> counts;
  std::string problem_name;  // the PDDL problem's name (the file stem)
};
// One random problem: its PDDL text and its map as text (problems/<P>.txt;
// empty when the pack draws none).
struct GeneratedProblem {
  std::string pddl;
  std::string picture;
};

// A literal-listener qualifier lookup: the (predicate object value) term of an object.
using QualifierOf = commands::QualifierLookup;

class Pack {
 public:
  explicit Pack(PackSpec spec);
  virtual ~Pack() = default;
  Pack(const Pack&) = delete;
  Pack& operator=(const Pack&) = delete;

  const PackSpec& spec() const { return spec_; }
  const std::string& name() const { return spec_.name; }
  const Roles& roles() const { return spec_.roles; }
  const commands::LanguageConfig& language() const { return spec_.language; }

  // ---- problems and plans ----
  // Rejects a grounded problem the pack cannot work with (InputError naming `path`).
  virtual void check_problem(const pddl::Task& task, const std::string& path) const;
  // Rejects an observed plan the pack cannot read (too many utterances).
  void check_observed_plan(const pddl::PlanFile& observed) const;
  // Rejects a plan tag the pack does not know (when it declares plan_tags).
  void check_plan_tag(const std::string& tag, const std::string& plan_id) const;

  // ---- goals ----
  // Candidate goals of a problem when the rule is Objects or ProblemGoal
  // (GoalSets are files, read by the dataset loader).
  std::vector<GoalSpec> problem_goals(const pddl::Task& task, const std::string& problem_path) const;
  // Index of the true goal among `goals`, for a plan with this tag and completion.
  int true_goal_index(const pddl::Task& task, const std::vector<GoalSpec>& goals, const std::string& tag,
                      const pddl::PlanFile& observed, const pddl::PlanFile& completed) const;

  // ---- costs ----
  ProfileSet profiles_for(const std::string& tag) const;
  // The default candidate profiles (a live session without a tag).
  std::vector<model::CostProfile> default_profiles() const { return profiles_for("").profiles; }
  // A profile by user-facing name: "unit", "task", or a declared profile's
  // name (mDKG also "1".."4").
  virtual model::CostProfile cost_profile(const std::string& which) const;

  // ---- heuristics ----
  // Names make_heuristic accepts, the default admissible one first.
  virtual std::vector<std::string> heuristic_names() const;
  std::string default_admissible_heuristic() const { return heuristic_names().front(); }
  virtual std::unique_ptr<heuristics::Heuristic> make_heuristic(const std::string& name,
                                                                const pddl::Task& task) const;

  // ---- language ----
  // Few-shot examples in prompt order: the speaker model's (pragmatic) or the
  // literal listener's. `language_dir` overrides the shared data/language.
  std::vector<commands::FewShotExample> fewshot(bool literal, const std::string& language_dir = "") const;

  // ---- literal listener ----
  // The assistant actions a literal command may name in state s (before
  // qualifiers): every ground action of a salient schema whose agent is the
  // listener; a pack may narrow it.
  virtual std::vector<commands::Term> literal_candidates(const pddl::Task& task, const pddl::State& s) const;
  // Qualifier terms from the problem's static facts of the language's qualifier predicate.
  virtual QualifierOf qualifier_of(const pddl::Task& task) const;
  // Goals that can never hold, so their search is skipped (mDKG: an item the
  // robot may not hold).
  virtual std::function<bool(const std::string&)> goal_unsatisfiable(const pddl::Task& task) const;

  // ---- assistance options ----
  // The option an assistant action commits to, for plans with `tag`.
  std::optional<std::string> option_of(const pddl::Task& task, pddl::ActionId a, const std::string& tag) const;
  // The options the assistant took in a completed plan (object names in order of first use).
  std::vector<std::string> options_taken(const pddl::PlanFile& completed, const std::string& tag,
                                         const pddl::Task* task = nullptr) const;
  // Is this object an option at all for plans with `tag`?
  bool is_option_object(const pddl::Task& task, const std::string& object, const std::string& tag) const;

  // ---- showing states ----
  // A text view of a state (what `clips show` and Session::state print).
  virtual std::string describe_state(const pddl::Task& task, const pddl::State& s) const;
  // Objects worth naming to an LLM, with their qualifier: "key1 (red), door1 (blue)".
  virtual std::string object_list(const pddl::Task& task) const;

  // ---- generating problems (`clips generate`) ----
  // One random problem. nullopt: this draw gave no acceptable layout (the
  // caller draws again, a bounded number of times); InputError: the
  // parameters can never work (naming the flag at fault). The caller checks
  // that every candidate goal is solvable. Default: InputError, the pack
  // cannot generate problems.
  virtual std::optional<GeneratedProblem> generate_problem(const GenerateParams& params, util::Rng& rng) const;
  // The object kinds generate_problem counts (empty: it cannot generate).
  virtual std::vector<std::string> generated_kinds() const { return {}; }

  // ---- outside planners ----
  // The task from `start` compiled to plain STRIPS with integer costs. By
  // default the grounded task as it is (domains/strips.hpp: tasks without
  // numeric fluents); mDKG's pack compiles its grid and numbers to atoms.
  virtual std::optional<StripsExport> export_strips(const pddl::Task& task, const pddl::State& start,
                                                    const std::string& goal, const model::CostProfile& costs) const;

 protected:
  PackSpec spec_;
};

using PackPtr = std::shared_ptr<const Pack>;

// The one candidate goal that holds after `observed` then `completed` from
// the initial state; a goal that is a part of another reached goal (its
// atoms a subset) does not count. InputError if none or several remain.
int reached_goal_index(const pddl::Task& task, const std::vector<GoalSpec>& goals, const pddl::PlanFile& observed,
                       const pddl::PlanFile& completed);

// Reads a pack file. Every error is an InputError naming the file and the
// field ("pack.json: goals.source: expected one of ..."). `domain` (if given)
// is the PDDL domain, checked against the names the file uses (actions,
// predicates, types, agents are checked when a problem is grounded).
PackSpec parse_pack_spec(const std::string& json_text, const std::string& source);
PackSpec load_pack_spec(const std::string& path);
// Checks a spec against a domain: every action, predicate and type it names
// exists. Throws InputError naming the field.
void check_pack_against(const PackSpec& spec, const pddl::Domain& domain);

// The pack for a domain:
//   1. `<dir>/pack.json` when `dir` is given and holds one;
//   2. `<data>/domains/<domain name>/pack.json` (util::data_dir());
//   3. the compiled-in pack of that name (doors-keys-gems, virtual-home);
//   4. the generic pack: everything defaulted (see docs/domains.md).
PackPtr find_pack(const pddl::Domain& domain, const std::string& dir = "");
// A pack from a spec: its "code" picks the compiled hooks ("" none).
PackPtr make_pack(PackSpec spec);
// The compiled-in specs (equal to data/domains/<name>/pack.json; tested).
std::vector<std::string> builtin_pack_names();
std::optional<PackSpec> builtin_pack_spec(const std::string& name);
// The compiled-in pack of that name; InputError listing the known ones.
PackPtr builtin_pack(const std::string& name);

std::string to_string(GoalSource s);
std::string to_string(SceneKind s);

}  // namespace clips::domains
