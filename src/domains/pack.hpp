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
#include "heuristics/registry.hpp"
#include "commands/command.hpp"
#include "commands/fewshot.hpp"
#include "commands/language_config.hpp"
#include "commands/salient.hpp"
#include "model/spec.hpp"
#include "model/turns.hpp"
#include "pddl/plan.hpp"
#include "pddl/task.hpp"
#include "util/choices.hpp"
#include "util/rng.hpp"

namespace clips::domains {

// One candidate goal: a label and a PDDL condition.
struct GoalSpec {
  std::string label;      // e.g. "gem2" or "set_table1"
  std::string condition;  // e.g. "(has human gem2)"
  std::string source;     // the file `condition` was read from ("" when built in code), for error locations
};

// How the agents take turns (roles.turns).
enum class TurnMode {
  Auto,       // Domain when the domain declares the turn predicate, else Alternate
  Domain,     // the domain writes its own turn idiom (the paper domains)
  Alternate,  // clips compiles turns in: principal, assistant, principal, ...
  Order,      // clips compiles turns in, in Roles::turn_order
};

// Who helps whom. The names the planning code asks (principal, assistant,
// no-op action, turn predicate) are model::TurnTaking's.
struct Roles : model::TurnTaking {
  int horizon = 100;                 // assistance episodes stop after this many steps
  // What doing nothing costs: the principal's no-op in the assistance value,
  // and, for a pack without cost_profiles, both agents' no-op in the default
  // profile (every other action 1). Below 1 so that equally short plans do
  // not differ by needless actions (the paper's profiles: 0.6); VirtualHome
  // sets 1 (unit costs).
  double noop_cost = 0.6;
  // For a pack without cost_profiles: how many times an assistant's action
  // each action of the principal but its no-op costs in the default profile,
  // for domains where people ask for help with what they would rather not do
  // themselves (the paper's mDKG profiles: human moves 2, robot 1). 1 by
  // default: docs/decisions.md ("A principal who may plan alone") has why.
  double principal_effort = 1.0;
  // The principal's simulated moves also take the k-th completed-plan action
  // when it is legal, even off the completed trajectory (VirtualHome).
  bool principal_follows_completed_plan = false;
  TurnMode turns = TurnMode::Auto;
  std::vector<std::string> turn_order;  // TurnMode::Order: agent object names, the first starts
  // The agents' type: the turn and freeze predicates range over it, and every
  // action's first parameter (the acting agent) must be of it.
  std::string agent_type = "agent";
};

// What clips adds to a pack's domain and problems before grounding (docs/
// domains.md, "What clips adds"), decided by plan_task_transform
// (task_transform.hpp) when find_pack checks the pack against the domain.
// Empty for the paper domains, which write the turn idiom and `frozen`.
struct TaskTransform {
  // (frozen ?a - agent_type), and (not (frozen ?a)) in the precondition of
  // every action but the no-op, ?a its first parameter.
  bool add_frozen = false;
  // The turn predicate and next-turn, (<turn> ?a) in every precondition, the
  // turn hand-over in every effect, and the initial facts of turn_order.
  bool compile_turns = false;
  bool add_noop = false;             // compile_turns: the domain lacks the no-op, clips adds it
  std::string agent_type;            // the agents' type (when anything is added)
  std::vector<std::string> turn_order;  // compile_turns: agents in turn order (the first starts)
  bool empty() const { return !add_frozen && !compile_turns; }
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
// speaker would say (docs/architecture.md, the utterance model).
struct RolloutSettings {
  enum class Kind { Greedy, WeightedAStar };
  Kind kind = Kind::Greedy;
  // WeightedAStar: this flag predicate is set on the speaker first (VH
  // "nograb": the rest of the work is left to the listener).
  std::string speaker_flag;
  // Greedy: which joint plans the speaker may have in mind. Tied: every
  // plan the policy values equally (ties broken every way, each way weighted
  // as a uniform random tie-break; search/tied_rollouts.hpp); Single: the one
  // greedy rollout (the paper packs, for their tables).
  enum class Plans { Single, Tied };
  Plans plans = Plans::Tied;
};
// inference.rollout.plans and --speaker-plans: "single" or "tied".
util::Choices<RolloutSettings::Plans>& speaker_plans_choices();

struct InferenceSettings {
  // Of the human model's policies. h_FF: informative, not admissible (h_max
  // values most actions alike, which leaves the actions no evidence).
  std::string heuristic = "hff";
  bool search = true;              // false: V = -h_g with no search (VH)
  double temperature_shape = 0.5;  // inverse-gamma prior on the Boltzmann temperature
  // Fitted with the alone twins on the dev halves (docs/decisions.md, "A
  // principal who may plan alone"): 0.25, the most tolerant of the scales
  // within 0.01 of the best log score.
  double temperature_scale = 0.25;
  RolloutSettings rollout;
  // The weight ε of the utterance model's noise: P(u | h) is read as
  // (1 - ε) P(u | h) + ε B(u), where B(u) is the mean of P(u | h') over the
  // hypotheses, so no reading can make a goal more than about 1/ε times
  // less likely than the others (inference/belief.hpp). 0: the bare model
  // (the paper packs, for their tables). Fitted on the dev halves of the
  // repo's own datasets (docs/decisions.md, "Robust utterance evidence").
  double utterance_noise = 0.05;
  // The exponent τ the robust utterance likelihood is raised to (the words
  // count as τ observations of the same reading): a calibration knob for a
  // pack whose language model is over- or under-confident. 1: the bare model.
  // A fit on the dev halves (τ = 2, ε = 0.2) did not carry over to the test
  // halves, so the default stays 1 (docs/decisions.md, "Robust utterance
  // evidence").
  double utterance_exponent = 1.0;
  // Each cost profile gets an alone twin (model::alone_twin) in which the
  // assistant's actions cost this many times as much: a principal who does
  // what is within reach instead of what the best joint plan leaves them
  // (people fetch the thing beside them even when the assistant could have).
  // Hypotheses are goal x profile, so the twin doubles them; the assistant
  // values a twin's hypotheses with its base profile. 0: no twins (the paper
  // packs). docs/decisions.md, "A principal who may plan alone".
  double alone_cost_factor = 4.0;
  // The share of the speaker model's plans that come from a delegating
  // principal: one whose joint plan has the assistant do all it usefully
  // can (its actions cost just above its no-op, roles.noop_cost + 0.1 times
  // the base profile's cost), so "could you fetch the plant?" is a likely
  // request where the cheapest joint plan has the principal fetch it
  // themselves. 0: the cooperative plans alone (the paper packs).
  // docs/decisions.md, "A speaker who would hand over any part".
  double speaker_delegates = 0.15;
  // Reading what an instruction asks the assistant to do, for assistance
  // only (the goal posterior does not change): besides the joint plans the
  // speaker model explains the words with, the commands of a sparing plan
  // (the joint plan in which the principal's own actions cost ten times as
  // much, so the assistant does all it can), in this share of the prior.
  // "Could you bring me the blue one?" then asks for the blue one's
  // hand-over even where every joint plan leaves the fetch to the principal.
  // 0: requests from the speaker model's commands alone (the paper packs).
  double request_plans = 0.15;
  // The share of the speaker model's plans that are sparing plans (above),
  // for the goal posterior: a speaker who asks for what they could fetch
  // themselves is then still explained by their goal. 0: none (the paper
  // packs).
  double sparing_plans = 0.05;
  // The share of the principal's action likelihood that is progress rather
  // than Boltzmann-rational choice: P(a | s, h) = (1 - ρ) Boltzmann(a) +
  // ρ Progress(a), where Progress is uniform over the principal's actions
  // that bring an atom of h's goal nearer by the principal's own h_max (the
  // assistant's actions 1000 times dearer), or over all its actions when
  // none does. People walk to the nearer of two things first although the
  // other order is cheaper; on a map each such step would otherwise count
  // many times against their goal. 0: the bare model (the paper packs).
  // Chosen on the dev halves (docs/decisions.md, "Progress in the action
  // likelihood").
  double progress_share = 0.05;
};

// The literal listener's variants, by the method names a bench runs them
// under: planning for a command as a lifted goal (efficient) or for its
// groundings one by one (naive). "literal" is the efficient one under the
// name VirtualHome's results use.
enum class LiteralPlanning { Efficient, Naive };
util::Choices<LiteralPlanning>& literal_method_choices();

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
  // and command language (lm/domain_corpus.hpp).
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
  // How Q_MDP breaks ties between equally good assistant actions
  // (assist::AssistRule): "request" (toward what the principal asked for) or
  // "paper" (the paper's rule as written; the paper packs, for their tables).
  std::string assistance_rule = "request";
  // Salient actions whose language.goal_atoms were derived from the domain's
  // effects (derive_goal_atoms), for `clips validate` to report.
  std::vector<std::string> derived_goal_atoms;
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
  // Not read from the file: what clips adds to the domain for this pack
  // (find_pack decides it against the domain; empty for a pack built
  // without one, and for the generic pack, which adds nothing).
  TaskTransform transform;
  // The generic pack (no pack file): clips adds nothing to the domain.
  bool generic = false;
};

// A task compiled to plain STRIPS for an outside planner (e.g. Fast Downward).
struct StripsExport {
  std::string domain;    // PDDL text of the STRIPS domain
  std::string problem;   // PDDL text of the STRIPS problem
  int cost_scale = 1;    // exported cost = original cost * cost_scale
  std::string goal;      // the goal as exported, e.g. "(and (has human gem2))"
  // Exported action name -> original ground action ("" for an action the
  // export adds), when the names do not say it (the generic export; mDKG's
  // names map back by domains::dkg::to_original_action).
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
  // The candidate profiles of a plan with this tag: the declared ones, then
  // (inference.alone_cost_factor > 0) the alone twin of each.
  ProfileSet profiles_for(const std::string& tag) const;
  // The declared profiles alone (or the default one).
  ProfileSet declared_profiles_for(const std::string& tag) const;
  // The one profile of a pack without cost_profiles: every assistant action
  // 1, every principal action roles.principal_effort, both agents' no-op
  // roles.noop_cost ("unit" when both are 1).
  model::CostProfile default_profile() const;
  // The default candidate profiles (a live session without a tag).
  std::vector<model::CostProfile> default_profiles() const { return profiles_for("").profiles; }
  // A profile by user-facing name: "unit", "task", or a declared profile's
  // name (mDKG also "1".."4").
  virtual model::CostProfile cost_profile(const std::string& which) const;

  // ---- heuristics ----
  // The pack's own heuristics (one name table, util/choices.hpp), offered
  // before the generic ones (heuristics/registry.hpp); none by default.
  virtual const util::Choices<heuristics::HeuristicMaker>* own_heuristics() const { return nullptr; }
  // The admissible heuristic `clips plan` and the generator search with by default.
  virtual std::string default_admissible_heuristic() const { return "lmcut"; }
  // Names make_heuristic accepts, the default admissible one first.
  std::vector<std::string> heuristic_names() const;
  // InputError listing heuristic_names for an unknown name.
  std::unique_ptr<heuristics::Heuristic> make_heuristic(const std::string& name, const pddl::Task& task) const;

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
  // A lower bound on the principal's own actions before the candidate goal
  // labelled `goal` holds, from `s` (nullopt: the pack cannot say). `clips
  // generate` refuses at once a plan no sampled sequence could fit into its
  // step limit (mDKG: the walk to the gem on the grid, doors open, and the
  // pick-up).
  virtual std::optional<int> min_principal_actions(const pddl::Task& task, const pddl::State& s,
                                                   const std::string& goal) const;
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
// The JSON Schema of pack files, data/schema/pack.schema.json under the data
// folder (util::data_dir()).
std::string pack_schema_path();
// The violations of that schema by a pack file's text, each "<field>:
// <what>" (empty: the text conforms). InputError when the text is not JSON
// or the schema cannot be read. parse_pack_spec checks more (values that
// depend on each other); the schema is what editors check as one types.
std::vector<std::string> pack_schema_errors(const std::string& json_text, const std::string& source,
                                            const std::string& schema_path = pack_schema_path());
// Checks a spec against a domain: every action, predicate and type it names
// exists, and what clips must add to the domain for it can be added
// (plan_task_transform). Throws InputError naming the field.
void check_pack_against(const PackSpec& spec, const pddl::Domain& domain);
// What a salient action means as a goal when the pack gives it no
// language.goal_atoms: the atoms its effect adds and the negations of those
// it deletes (unconditional effects only) that name its focal object, e.g.
// (unlock ?a ?k ?d) adding (unlocked ?d) and deleting (locked ?d) gives
// {"(unlocked $3)", "(not (locked $3))"}; the turn and freeze bookkeeping
// (`turn_predicate`, `frozen`) is left out. Empty when no such effect exists.
std::vector<std::string> goal_atoms_from_effects(const pddl::Domain& domain, const commands::SalientActionRule& rule,
                                                 const std::string& turn_predicate);
// Fills language.goal_atoms of every salient action the pack leaves out (and
// whose effects say something, see above) and lists them in
// PackSpec::derived_goal_atoms.
void derive_goal_atoms(PackSpec& spec, const pddl::Domain& domain);
// The predicates that say where an object is (language.location_predicates),
// when the pack leaves them to "auto": the places are the types of the second
// argument of a binary predicate some action changes for an agent (where an
// agent is, (at ?a - agent ?s - station)); a location predicate relates a
// first argument that is not an agent type to such a place and some action
// changes it ((on ?i - item ?s - station), or one (at ?x - locatable ?p -
// place) for agents and items alike).
std::vector<std::string> location_predicates(const pddl::Domain& domain, const std::string& agent_type);
void derive_location_predicates(PackSpec& spec, const pddl::Domain& domain);
// Each salient action's destination_arg: the parameter P (neither its agent
// nor its focal object I) such that the action adds (L I P) for a location
// predicate L, as (put ?a ?i ?p) adds (in ?i ?p). Run after the location
// predicates are known; nothing when language.destinations is false. Also
// each rule's focal_is_place: its focal parameter's type is a place type of a
// location predicate (unlock's place) and not a type such a predicate locates
// (a block on a block), whatever language.destinations says.
void derive_destinations(PackSpec& spec, const pddl::Domain& domain);

// Finding a domain's pack, in three parts so that the compiled hooks (a
// spec's "code", src/domains/dkg and src/domains/vh) stay out of this
// library: domains/builtin/packs.hpp joins them (find_pack, make_pack).
// The declared spec of a domain, the first of:
//   1. `<dir>/pack.json` when `dir` is given and holds one;
//   2. `<data>/domains/<domain name>/pack.json` (util::data_dir());
//   3. the compiled-in spec of that name (builtin_pack_spec);
// none when the domain has no pack.
std::optional<PackSpec> declared_pack_spec(const pddl::Domain& domain, const std::string& dir = "");
// The generic spec of a domain without a pack: everything defaulted (see
// docs/domains.md), with what it derives from the domain.
PackSpec generic_pack_spec(const pddl::Domain& domain);
// A declared spec made the spec of a domain: checked against it
// (check_pack_against), with what clips adds (PackSpec::transform) and what
// it derives from the domain (goal atoms, location predicates).
PackSpec pack_spec_for_domain(PackSpec spec, const pddl::Domain& domain);
// What a pack's compiled hooks read from a domain: types, and predicates and
// functions with their arity.
struct DomainNeeds {
  std::vector<const char*> types;
  std::vector<std::pair<const char*, size_t>> predicates, functions;  // name, arity
};
// What the domain lacks of `needs`, e.g. "no function (walls)"; "" when nothing.
std::string domain_misfit(const pddl::Domain& domain, const DomainNeeds& needs);
// The compiled-in specs (equal to data/domains/<name>/pack.json; tested).
std::vector<std::string> builtin_pack_names();
std::optional<PackSpec> builtin_pack_spec(const std::string& name);

std::string to_string(GoalSource s);
std::string to_string(SceneKind s);

}  // namespace clips::domains
