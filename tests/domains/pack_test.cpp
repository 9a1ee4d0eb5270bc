// Domain packs: reading pack.json (every error names the field), the
// compiled-in packs of the paper domains, and what a pack derives from its
// data (goals, true goals, profiles, options, candidates).
#include "domains/builtin/packs.hpp"
#include "domains/pack.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <fstream>
#include <unistd.h>

#include "paper_languages.hpp"
#include "data/dataset.hpp"
#include <nlohmann/json.hpp>

#include "commands/term.hpp"
#include "model/spec.hpp"
#include "pddl/parser.hpp"
#include "util/error.hpp"

namespace clips::domains {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string error_of(const std::string& json) {
  try {
    parse_pack_spec(json, "t/pack.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_same(const commands::LanguageConfig& a, const commands::LanguageConfig& b) {
  EXPECT_EQ(a.domain, b.domain);
  ASSERT_EQ(a.salient_actions.size(), b.salient_actions.size());
  for (std::size_t i = 0; i < a.salient_actions.size(); ++i) {
    EXPECT_EQ(a.salient_actions[i].action, b.salient_actions[i].action);
    EXPECT_EQ(a.salient_actions[i].agent_arg, b.salient_actions[i].agent_arg);
    EXPECT_EQ(a.salient_actions[i].focal_arg, b.salient_actions[i].focal_arg);
  }
  EXPECT_EQ(a.qualifier, b.qualifier);
  EXPECT_EQ(a.qualifier_object_arg, b.qualifier_object_arg);
  EXPECT_EQ(a.speaker, b.speaker);
  EXPECT_EQ(a.listener, b.listener);
  EXPECT_EQ(a.speaker_pronoun, b.speaker_pronoun);
  EXPECT_EQ(a.listener_pronoun, b.listener_pronoun);
  EXPECT_EQ(a.max_command_actions, b.max_command_actions);
  EXPECT_EQ(a.max_action_types, b.max_action_types);
  EXPECT_EQ(a.max_qualifier_values_per_action_type, b.max_qualifier_values_per_action_type);
  EXPECT_EQ(a.speaker_actions, b.speaker_actions);
  EXPECT_EQ(a.exclude_chains, b.exclude_chains);
  EXPECT_EQ(a.paper_speaker_actions, b.paper_speaker_actions);
  EXPECT_EQ(a.paper_exclude_chains, b.paper_exclude_chains);
  EXPECT_EQ(a.variable_naming, b.variable_naming);
  EXPECT_EQ(a.printed_form, b.printed_form);
  EXPECT_EQ(a.goal_atoms, b.goal_atoms);
  EXPECT_EQ(a.goal_variables, b.goal_variables);
}

// The paper packs' language blocks are the command models the paper's
// numbers were measured with (tests/paper_languages.hpp writes them out).
TEST(BuiltinPacks, LanguageBlocksEqualThePaperCommandModels) {
  expect_same(builtin_pack_spec("doors-keys-gems")->language, commands::doors_keys_gems_language());
  expect_same(builtin_pack_spec("virtual-home")->language, commands::virtual_home_language());
}

// The compiled-in copy is the shipped file: the shipped file parses to the same spec.
TEST(BuiltinPacks, CompiledCopiesEqualTheShippedFiles) {
  for (const auto& name : builtin_pack_names()) {
    const PackSpec shipped = load_pack_spec(CLIPS_SOURCE_DIR "/data/domains/" + name + "/pack.json");
    const PackSpec built = *builtin_pack_spec(name);
    expect_same(shipped.language, built.language);
    EXPECT_EQ(shipped.roles.assistant, built.roles.assistant);
    EXPECT_EQ(shipped.inference.heuristic, built.inference.heuristic);
    EXPECT_EQ(shipped.cost_profiles.size(), built.cost_profiles.size());
    EXPECT_EQ(shipped.rules_text, built.rules_text);
    EXPECT_EQ(shipped.scene_colours, built.scene_colours);
  }
  EXPECT_EQ(builtin_pack_names(), (std::vector<std::string>{"doors-keys-gems", "virtual-home"}));
}

// clips-spec.md 4.2, written out here so the test does not read the pack to
// check the pack: the human's pickup 5 and wait 0.6 everywhere, its other
// actions 2 under C2/C4; the robot's unlock 5 under C3/C4, its other
// actions 1, wait 0.6.
model::CostProfile paper_profile(int index) {
  model::CostProfile p;
  const double human = index == 2 || index == 4 ? 2.0 : 1.0;
  for (const char* a : {"up", "down", "left", "right", "unlock", "handover"}) p.costs[{"human", a}] = human;
  p.costs[{"human", "pickup"}] = 5.0;
  p.costs[{"human", "wait"}] = 0.6;
  for (const char* a : {"up", "down", "left", "right", "pickup", "handover"}) p.costs[{"robot", a}] = 1.0;
  p.costs[{"robot", "unlock"}] = index >= 3 ? 5.0 : 1.0;
  p.costs[{"robot", "wait"}] = 0.6;
  return p;
}

TEST(BuiltinPacks, PaperSettings) {
  auto dkg = builtin_pack("doors-keys-gems");
  EXPECT_EQ(dkg->roles().principal, "human");
  EXPECT_EQ(dkg->roles().noop_cost, 0.6);
  EXPECT_EQ(dkg->spec().inference.heuristic, "dkg-mst");
  EXPECT_EQ(dkg->default_admissible_heuristic(), "dkg-dist");
  // keys {C3, C4}, doors {C1, C2}, each equal to the paper's table.
  auto keys = dkg->profiles_for("keys");
  ASSERT_EQ(keys.profiles.size(), 2u);
  EXPECT_EQ(keys.profiles[0].name, "C3");
  EXPECT_EQ(keys.profiles[0].costs, paper_profile(3).costs);
  EXPECT_EQ(keys.profiles[1].costs, paper_profile(4).costs);
  auto doors = dkg->profiles_for("doors");
  ASSERT_EQ(doors.profiles.size(), 2u);
  EXPECT_EQ(doors.profiles[0].costs, paper_profile(1).costs);
  EXPECT_EQ(doors.profiles[1].costs, paper_profile(2).costs);
  EXPECT_THROW(dkg->check_plan_tag("gems", "1.1.gems"), InputError);
  // "C2", "c2" and "2" all name C2; anything else is an error naming the choices.
  for (const char* name : {"C2", "c2", "2"}) {
    const model::CostProfile c2 = dkg->cost_profile(name);
    EXPECT_EQ(c2.name, "C2") << name;
    EXPECT_EQ(c2.costs, paper_profile(2).costs) << name;
    EXPECT_EQ(c2.default_cost, 1.0) << name;
  }
  for (const char* bad : {"5", "C0", "C12", ""}) EXPECT_THROW(dkg->cost_profile(bad), InputError) << bad;
  auto vh = builtin_pack("virtual-home");
  EXPECT_EQ(vh->roles().assistant, "helper");
  EXPECT_EQ(vh->roles().horizon, 50);
  EXPECT_FALSE(vh->spec().inference.search);
  EXPECT_EQ(vh->profiles_for("anything").profiles.size(), 1u);
  EXPECT_EQ(vh->spec().grounding.schema_order.front(), "grab");
  EXPECT_THROW(builtin_pack("sokoban"), InputError);
}

TEST(PackFile, MinimalFileTakesTheDefaults) {
  const PackSpec s = parse_pack_spec(R"j({"domain": "kitchen"})j", "t/pack.json");
  EXPECT_EQ(s.name, "kitchen");
  EXPECT_EQ(s.roles.principal, "human");
  EXPECT_EQ(s.roles.assistant, "robot");
  EXPECT_EQ(s.goals.source, GoalSource::ProblemGoal);
  EXPECT_EQ(s.inference.heuristic, "hff");
  EXPECT_TRUE(s.cost_profiles.empty());
  EXPECT_EQ(s.scene, SceneKind::Text);
  EXPECT_TRUE(s.grounding.keep_dynamic.count("frozen"));
}

TEST(PackFile, ErrorsNameTheFileAndTheField) {
  EXPECT_NE(error_of("{").find("t/pack.json"), std::string::npos);
  EXPECT_NE(error_of("{").find("invalid JSON"), std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "roles": {"horizon": 1e999}})j").find("invalid JSON"), std::string::npos);
  EXPECT_NE(error_of(R"j({"roles": {}})j").find("domain: missing"), std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "colour": 1})j").find("colour: unknown field"), std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "roles": {"horizon": 0}})j").find("roles.horizon"), std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "roles": {"principal": "a", "assistant": "a"}})j").find("roles.assistant"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "goals": {"source": "somewhere"}})j").find("goals.source: expected one of"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "goals": {"source": "objects", "object_type": "gem", "condition": "(has human gem)"}})j")
                .find("goals.condition"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "cost_profiles": [{"profiles": [{"name": "c", "costs": {"human": {"move": -1}}}]}]})j")
                .find("cost_profiles[0].profiles[0].costs.human.move"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "language": {"salient_actions": []}})j").find("language: salient_actions"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "language": {"salient_actions": [{"action": "get", "focal_arg": 2}],
                          "speaker": {"object": "alice", "pronoun": "me"}}})j")
                .find("language.speaker.object"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "literal_listener": {"methods": ["psychic"]}})j").find("literal_listener.methods[0]"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "assistance_options": [{"action": "get"}]})j").find("assistance_options[0].object_arg"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "inference": {"temperature_prior": {"shape": 0}}})j")
                .find("inference.temperature_prior.shape"),
            std::string::npos);
}

// A small two-agent domain written for this test.
constexpr const char* kDomain = R"((define (domain pantry)
  (:requirements :strips :typing :negative-preconditions)
  (:types agent item - object fruit tool - item)
  (:predicates (has ?a - agent ?i - item) (at ?i - item) (isripe ?i - item ?v - item) (frozen ?a - agent))
  (:action take :parameters (?a - agent ?i - item)
    :precondition (and (at ?i) (not (frozen ?a))) :effect (and (has ?a ?i) (not (at ?i))))
  (:action give :parameters (?a - agent ?b - agent ?i - item)
    :precondition (and (has ?a ?i) (not (frozen ?a))) :effect (and (has ?b ?i) (not (has ?a ?i))))
  (:action wait :parameters (?a - agent) :precondition (and) :effect (and))))";
constexpr const char* kProblem = R"((define (problem p1) (:domain pantry)
  (:objects cook helper - agent apple pear - fruit knife - tool)
  (:init (at apple) (at pear) (at knife))
  (:goal (has cook apple))))";

struct Pantry {
  Pantry() {
    dir = fs::temp_directory_path() / ("clips-pack-test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "domain.pddl") << kDomain;
    std::ofstream(dir / "p1.pddl") << kProblem;
    domain = std::make_shared<pddl::Domain>(pddl::load_domain((dir / "domain.pddl").string()));
  }
  ~Pantry() { fs::remove_all(dir); }
  fs::path dir;
  std::shared_ptr<pddl::Domain> domain;
};

// The problem's action written as `text` ("(take cook apple)"); a failure
// (and action 0) when there is none.
pddl::ActionId action_id(const pddl::Task& task, const std::string& text) {
  if (auto a = task.find_action(text)) return *a;
  ADD_FAILURE() << "no action " << text;
  return pddl::ActionId{0};
}

constexpr const char* kPantryPack = R"j({
  "domain": "pantry",
  "roles": {"principal": "cook", "assistant": "helper", "turns": ["helper", "cook"]},
  "goals": {"source": "objects", "object_type": "fruit", "condition": "(has cook {})"},
  "language": {"salient_actions": [{"action": "take", "focal_arg": 2}, {"action": "give", "focal_arg": 3}],
               "qualifier": {"predicate": "isripe"}},
  "assistance_options": [{"action": "take", "object_arg": 2, "object_type": "fruit"}]
})j";

// roles.principal_effort: in the default profile the principal's actions but
// its no-op cost that many times the assistant's; the alone twin keeps it and
// scales the assistant's on top. 1 (the default) leaves unit costs.
TEST(PackFile, PrincipalEffortScalesThePrincipalsActionsInTheDefaultProfile) {
  Pantry p;
  std::string text = kPantryPack;
  text.replace(text.find(R"("turns": ["helper", "cook"]})"), std::string(R"("turns": ["helper", "cook"]})").size(),
               R"("turns": ["helper", "cook"], "principal_effort": 2.5})");
  std::ofstream(p.dir / "pack.json") << text;
  PackPtr pack = find_pack(*p.domain, p.dir.string());
  auto task = data::ground_problem(*pack, p.domain, (p.dir / "p1.pddl").string());
  const ProfileSet set = pack->profiles_for("");
  ASSERT_EQ(set.profiles.size(), 2u);
  const model::Specification base(task, "(has cook apple)", set.profiles[0]);
  const model::Specification alone(task, "(has cook apple)", set.profiles[1]);
  auto id = [&](const std::string& a) { return action_id(*task, a); };
  EXPECT_DOUBLE_EQ(base.cost(id("(take cook apple)")), 2.5);
  EXPECT_DOUBLE_EQ(base.cost(id("(wait cook)")), 0.6);
  EXPECT_DOUBLE_EQ(base.cost(id("(take helper apple)")), 1.0);
  EXPECT_DOUBLE_EQ(alone.cost(id("(take cook apple)")), 2.5);
  EXPECT_DOUBLE_EQ(alone.cost(id("(take helper apple)")), 4.0);
  EXPECT_DOUBLE_EQ(alone.cost(id("(wait helper)")), 0.6);
  // The sparing plans' scaling of the principal multiplies it.
  const model::Specification sparing(task, "(has cook apple)",
                                     model::scaled_assistant(set.profiles[0], "s", "cook", "wait", 10));
  EXPECT_DOUBLE_EQ(sparing.cost(id("(take cook apple)")), 25.0);
  EXPECT_DOUBLE_EQ(sparing.cost(id("(wait cook)")), 0.6);
  EXPECT_EQ(parse_pack_spec(R"j({"domain": "k"})j", "t/pack.json").roles.principal_effort, 1.0);
  EXPECT_NE(error_of(R"j({"domain": "k", "roles": {"principal_effort": 0}})j").find("roles.principal_effort"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "roles": {"principal_effort": 1001}})j").find("roles.principal_effort"),
            std::string::npos);
}

TEST(PackFile, TurnsTurnPredicateAndAgentType) {
  PackSpec s = parse_pack_spec(R"j({"domain": "k"})j", "t/pack.json");
  EXPECT_EQ(s.roles.turns, TurnMode::Auto);
  EXPECT_EQ(s.roles.turn_predicate, "active");
  EXPECT_EQ(s.roles.noop_action, "wait");
  EXPECT_EQ(s.roles.agent_type, "agent");
  s = parse_pack_spec(R"j({"domain": "k", "roles": {"turns": "alternate", "turn_predicate": "turn", "noop_action": "idle",
                           "agent_type": "person"}})j",
                      "t/pack.json");
  EXPECT_EQ(s.roles.turns, TurnMode::Alternate);
  EXPECT_EQ(s.roles.turn_predicate, "turn");
  EXPECT_EQ(s.roles.agent_type, "person");
  // The pack's roles are the turn-taking the planning code asks.
  const model::TurnTaking& t = s.roles;
  EXPECT_EQ(t.noop_action, "idle");
  s = parse_pack_spec(R"j({"domain": "k", "roles": {"turns": ["robot", "dog", "human"]}})j", "t/pack.json");
  EXPECT_EQ(s.roles.turns, TurnMode::Order);
  EXPECT_EQ(s.roles.turn_order, (std::vector<std::string>{"robot", "dog", "human"}));
  EXPECT_NE(error_of(R"j({"domain": "k", "roles": {"turns": ["human", "dog"]}})j").find("must include roles.assistant 'robot'"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "roles": {"turns": ["human", "robot", "human"]}})j").find("roles.turns[2]"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "roles": {"turns": true}})j").find("roles.turns: expected \"domain\""),
            std::string::npos);
}

TEST(PackFile, AMissingFewShotFileNamesTheField) {
  Pantry p;
  std::ofstream(p.dir / "pack.json") << R"j({"domain": "pantry", "roles": {"principal": "cook", "assistant": "helper"},
                                             "fewshot": {"file": "examples.tsv"}})j";
  try {
    find_pack(*p.domain, p.dir.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fewshot.file: no file"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("examples.tsv"), std::string::npos) << e.what();
  }
}

// issue 46: what passed the pack reader and failed (or hung) later.
TEST(PackFile, GoalAtomArgumentsCommandSizeAndCostsAreChecked) {
  Pantry p;
  auto with_atoms = [&](const std::string& atoms) {
    json pack = json::parse(kPantryPack);
    pack["language"]["goal_atoms"] = json::parse(atoms);
    std::ofstream(p.dir / "pack.json") << pack.dump();
    try {
      find_pack(*p.domain, p.dir.string());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(with_atoms(R"j({"take": ["(has $1 $2)"], "give": ["(has $2 $3)"]})j"), "");
  std::string e = with_atoms(R"j({"take": ["(has $1 $2)"], "give": ["(has $2 $3)", "(has $1 $7)"]})j");
  EXPECT_NE(e.find("language.goal_atoms.give[1]"), std::string::npos) << e;
  EXPECT_NE(e.find("'$7'"), std::string::npos) << e;
  EXPECT_NE(e.find("has 3"), std::string::npos) << e;
  e = with_atoms(R"j({"take": ["(has $1 $x)"]})j");
  EXPECT_NE(e.find("is not an argument reference"), std::string::npos) << e;
  e = with_atoms(R"j({"take": ["(has $0 $1)"]})j");
  EXPECT_NE(e.find("names parameter 0"), std::string::npos) << e;

  // A grid scene on a domain without the map's fluents (it failed when drawn).
  {
    json pack = json::parse(kPantryPack);
    pack["scene"] = "grid";
    std::ofstream(p.dir / "pack.json") << pack.dump();
    try {
      find_pack(*p.domain, p.dir.string());
      ADD_FAILURE() << "a grid scene without (walls) was accepted";
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find("scene: \"grid\" draws Doors-Keys-Gems maps"), std::string::npos)
          << err.what();
    }
  }

  const std::string lang = R"j("language": {"salient_actions": [{"action": "get", "focal_arg": 1}], "max_command_actions": )j";
  EXPECT_EQ(error_of(R"j({"domain": "k", )j" + lang + "4}}"), "");
  e = error_of(R"j({"domain": "k", )j" + lang + "5}}");
  EXPECT_NE(e.find("max_command_actions: 5 is more than 4"), std::string::npos) << e;

  for (const char* bad : {"0", "1e308", "-1", "1e7"}) {
    e = error_of(std::string(R"j({"domain": "k", "cost_profiles": [{"profiles": [{"name": "c", "default": )j") + bad + "}]}]}");
    EXPECT_NE(e.find(".default: expected a finite number > 0 and <= 1e+06"), std::string::npos) << bad << ": " << e;
  }
  e = error_of(R"j({"domain": "k", "cost_profiles": [{"profiles": [{"name": "c", "costs": {"human": {"move": 1e300}}}]}]})j");
  EXPECT_NE(e.find("costs.human.move"), std::string::npos) << e;
  EXPECT_EQ(error_of(R"j({"domain": "k", "cost_profiles": [{"profiles": [{"name": "c", "default": 2, "costs": {"human": {"wait": 0}}}]}]})j"),
            "");
}

TEST(PackFile, SceneColoursAreHexByType) {
  const PackSpec s = parse_pack_spec(
      R"j({"domain": "k", "scene": "cards", "scene_colours": {"comment": "x", "plate": "#A8c8f5", "shelf": "#000000"}})j",
      "t/pack.json");
  EXPECT_EQ(s.scene_colours, (std::map<std::string, std::string>{{"plate", "#A8c8f5"}, {"shelf", "#000000"}}));
  for (const char* bad : {R"j("#12345")j", R"j("12345678")j", R"j("#12345g")j", "7"}) {
    const std::string e = error_of(std::string(R"j({"domain": "k", "scene_colours": {"plate": )j") + bad + "}}");
    EXPECT_NE(e.find("scene_colours.plate"), std::string::npos) << bad << ": " << e;
  }
  EXPECT_NE(error_of(R"j({"domain": "k", "scene_colours": {"plate2": "#000000"}})j").find("trailing digits"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "scene_colours": ["#000000"]})j").find("scene_colours"), std::string::npos);
  // The bundled card pack colours every fixture type of its problems.
  const auto vh = builtin_pack_spec("virtual-home");
  for (const char* type : {"table", "cabinet", "fridge", "plate"}) EXPECT_TRUE(vh->scene_colours.count(type)) << type;
}

TEST(PackFile, CheckedAgainstTheDomain) {
  Pantry p;
  PackSpec s = parse_pack_spec(kPantryPack, "pantry/pack.json");
  EXPECT_NO_THROW(check_pack_against(s, *p.domain));
  s.goals.object_type = "vegetable";
  try {
    check_pack_against(s, *p.domain);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("goals.object_type"), std::string::npos) << e.what();
  }
  s = parse_pack_spec(kPantryPack, "pantry/pack.json");
  s.language.salient_actions[1].focal_arg = 4;
  EXPECT_THROW(check_pack_against(s, *p.domain), InputError);
  s = parse_pack_spec(kPantryPack, "pantry/pack.json");
  s.name = "kitchen";
  EXPECT_THROW(check_pack_against(s, *p.domain), InputError);
}

TEST(PackFile, AFolderPackIsFoundAndDrivesGoalsOptionsAndCandidates) {
  Pantry p;
  std::ofstream(p.dir / "pack.json") << kPantryPack;
  PackPtr pack = find_pack(*p.domain, p.dir.string());
  ASSERT_EQ(pack->name(), "pantry");
  auto task = data::ground_problem(*pack, p.domain, (p.dir / "p1.pddl").string());
  const auto goals = pack->problem_goals(*task, "p1.pddl");
  ASSERT_EQ(goals.size(), 2u);
  EXPECT_EQ(goals[0].label, "apple");
  EXPECT_EQ(goals[1].condition, "(has cook pear)");
  // The completion that ends with the cook holding the pear pursued "pear".
  // The helper acts first (roles.turns), the cook waits in its turns.
  pddl::PlanFile observed, completed;
  observed.actions.push_back({"(take helper knife)", SourceLoc{"obs", 1, 1}});
  completed.actions.push_back({"(wait cook)", SourceLoc{"comp", 1, 1}});
  completed.actions.push_back({"(take helper pear)", SourceLoc{"comp", 2, 1}});
  completed.actions.push_back({"(wait cook)", SourceLoc{"comp", 3, 1}});
  completed.actions.push_back({"(give helper cook pear)", SourceLoc{"comp", 4, 1}});
  EXPECT_EQ(pack->true_goal_index(*task, goals, "", observed, completed), 1);
  // Options: fruit the helper takes (the knife is no option).
  EXPECT_EQ(pack->options_taken(completed, "", task.get()), (std::vector<std::string>{"pear"}));
  EXPECT_TRUE(pack->is_option_object(*task, "apple", ""));
  EXPECT_FALSE(pack->is_option_object(*task, "knife", ""));
  // Literal candidates: every ground salient action of the helper.
  const auto cands = pack->literal_candidates(*task, task->initial_state());
  std::vector<std::string> printed;
  for (const auto& c : cands) printed.push_back(commands::to_pddl(c));
  EXPECT_NE(std::find(printed.begin(), printed.end(), "(take helper apple)"), printed.end());
  EXPECT_NE(std::find(printed.begin(), printed.end(), "(give helper cook pear)"), printed.end());
  for (const auto& c : cands) EXPECT_EQ(c.args[0], "helper");
  // Unit costs but a cheaper no-op (roles.noop_cost, 0.6), LM-cut, the generic text view.
  EXPECT_EQ(pack->default_profiles().front().name, "default");
  EXPECT_EQ(pack->default_admissible_heuristic(), "lmcut");
  EXPECT_NE(pack->describe_state(*task, task->initial_state()).find("(at apple)"), std::string::npos);
}

// Every declared profile gets an alone twin: the same costs but the
// assistant's actions, except its no-op, inference.alone_cost_factor times
// dearer; the twin names its base. 0 turns the twins off; the paper packs do.
TEST(PackFile, EveryProfileHasAnAloneTwinWhoseAssistantCostsMore) {
  Pantry p;
  std::ofstream(p.dir / "pack.json") << kPantryPack;
  PackPtr pack = find_pack(*p.domain, p.dir.string());
  auto task = data::ground_problem(*pack, p.domain, (p.dir / "p1.pddl").string());
  const ProfileSet set = pack->profiles_for("");
  ASSERT_EQ(set.profiles.size(), 2u);
  EXPECT_EQ(set.true_index, 0);
  EXPECT_EQ(set.profiles[0].name, "default");
  EXPECT_EQ(set.profiles[0].twin_of, -1);
  EXPECT_EQ(set.profiles[1].name, "default-alone");
  EXPECT_EQ(set.profiles[1].twin_of, 0);
  const model::Specification base(task, "(has cook apple)", set.profiles[0]);
  const model::Specification alone(task, "(has cook apple)", set.profiles[1]);
  auto id = [&](const std::string& a) { return action_id(*task, a); };
  EXPECT_DOUBLE_EQ(base.cost(id("(take helper apple)")), 1.0);
  EXPECT_DOUBLE_EQ(alone.cost(id("(take helper apple)")), 4.0);
  EXPECT_DOUBLE_EQ(alone.cost(id("(wait helper)")), 0.6);
  EXPECT_DOUBLE_EQ(alone.cost(id("(take cook apple)")), 1.0);
  EXPECT_DOUBLE_EQ(alone.cost(id("(wait cook)")), 0.6);
  // Named, as --costs and a session's cost_profiles name them; a set of
  // chosen names links each twin to its base.
  std::vector<model::CostProfile> chosen{pack->cost_profile("default-alone"), pack->cost_profile("default")};
  EXPECT_EQ(chosen[0].twin_of, -1);
  model::link_alone_twins(chosen);
  EXPECT_EQ(chosen[0].twin_of, 1);
  EXPECT_EQ(chosen[1].twin_of, -1);
  EXPECT_DOUBLE_EQ(model::Specification(task, "(has cook apple)", chosen[0]).cost(id("(take helper apple)")), 4.0);
  EXPECT_THROW(pack->cost_profile("C9-alone"), InputError);
  // The paper packs keep their declared profiles only.
  EXPECT_EQ(builtin_pack("doors-keys-gems")->profiles_for("keys").profiles.size(), 2u);
  EXPECT_EQ(builtin_pack("virtual-home")->profiles_for("").profiles.size(), 1u);
  EXPECT_EQ(parse_pack_spec(R"j({"domain": "k", "inference": {"alone_cost_factor": 0}})j", "t/pack.json")
                .inference.alone_cost_factor,
            0.0);
  EXPECT_NE(error_of(R"j({"domain": "k", "inference": {"alone_cost_factor": 0.5}})j").find("inference.alone_cost_factor"),
            std::string::npos);
  EXPECT_NE(error_of(R"j({"domain": "k", "inference": {"alone_cost_factor": "big"}})j").find("inference.alone_cost_factor"),
            std::string::npos);
}

// Where an action leaves its focal object comes from its effects: the garden's
// (put ?a ?i ?p) adds (in ?i ?p), so its destination is ?p; pickup and
// handover add no location of their item; the paper packs state none.
TEST(PackFile, DestinationsComeFromTheEffects) {
  const std::string garden = std::string(CLIPS_SOURCE_DIR) + "/data/datasets/garden";
  const DomainWithPack g = load_domain_with_pack(garden + "/domain.pddl", garden);
  std::map<std::string, int> destination;
  for (const auto& r : g.pack->spec().language.salient_actions) destination[r.action] = r.destination_arg;
  EXPECT_EQ(destination.at("put"), 3);
  EXPECT_EQ(destination.at("pickup"), 0);
  EXPECT_EQ(destination.at("handover"), 0);
  EXPECT_EQ(destination.at("unlock"), 0);
  // "destinations": false turns them off.
  PackSpec spec = g.pack->spec();
  spec.language.destinations = false;
  derive_destinations(spec, *g.domain);
  for (const auto& r : spec.language.salient_actions) EXPECT_EQ(r.destination_arg, 0) << r.action;
  EXPECT_NE(error_of(R"j({"domain": "k", "language": {"salient_actions": [{"action": "get", "focal_arg": 2}],
                          "destinations": "yes"}})j")
                .find("language: destinations: expected true or false"),
            std::string::npos);
  const std::string dkg = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";
  for (const auto& r : load_domain_with_pack(dkg + "/domain.pddl", dkg).pack->spec().language.salient_actions)
    EXPECT_EQ(r.destination_arg, 0) << r.action;
}

// The focal object of the garden's unlock is a place (the type of the second
// argument of its location predicate "in"), so commands name it; the items of
// pickup and put are not places; nothing is a place in a pack without
// location predicates, as the paper packs.
TEST(PackFile, AFocalPlaceIsKnownFromTheLocationPredicates) {
  const std::string garden = std::string(CLIPS_SOURCE_DIR) + "/data/datasets/garden";
  const DomainWithPack g = load_domain_with_pack(garden + "/domain.pddl", garden);
  std::map<std::string, bool> place;
  for (const auto& r : g.pack->spec().language.salient_actions) place[r.action] = r.focal_is_place;
  EXPECT_TRUE(place.at("unlock"));
  EXPECT_FALSE(place.at("pickup"));
  EXPECT_FALSE(place.at("put"));
  EXPECT_FALSE(place.at("handover"));
  PackSpec spec = g.pack->spec();
  spec.language.location_predicates.clear();
  derive_destinations(spec, *g.domain);
  for (const auto& r : spec.language.salient_actions) EXPECT_FALSE(r.focal_is_place) << r.action;
  const std::string dkg = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";
  for (const auto& r : load_domain_with_pack(dkg + "/domain.pddl", dkg).pack->spec().language.salient_actions)
    EXPECT_FALSE(r.focal_is_place) << r.action;
  // Blocks stacked on blocks: (on ?x - block ?y - block) says where a block
  // is, so blocks are places, but they are located too: pickup's block stays
  // a lifted thing; the table it is put on is only a place.
  const char* blocks = R"(
(define (domain stack)
  (:requirements :strips :typing)
  (:types agent block table)
  (:predicates (holding ?a - agent ?b - block) (on ?x - block ?y - block) (ontable ?x - block ?t - table)
               (clean ?t - table))
  (:action pickup :parameters (?a - agent ?b - block ?c - block)
   :precondition (on ?b ?c) :effect (and (not (on ?b ?c)) (holding ?a ?b)))
  (:action wipe :parameters (?a - agent ?t - table) :effect (clean ?t))
  (:action stack :parameters (?a - agent ?b - block ?c - block)
   :precondition (holding ?a ?b) :effect (and (not (holding ?a ?b)) (on ?b ?c))))
)";
  const pddl::Domain d = pddl::parse_domain(blocks, "stack.pddl");
  PackSpec stack = parse_pack_spec(R"j({"domain": "stack", "language": {"salient_actions": [
      {"action": "pickup", "focal_arg": 2}, {"action": "wipe", "focal_arg": 2}], "locations": ["on", "ontable"]}})j",
                                   "stack/pack.json");
  derive_location_predicates(stack, d);
  EXPECT_FALSE(stack.language.salient_actions[0].focal_is_place);
  EXPECT_TRUE(stack.language.salient_actions[1].focal_is_place);
}

// A domain that says where agents and items are with one predicate, (at ?x -
// locatable ?p - place), still has a location predicate, and its put a
// destination; one with (at ?a - agent ...) for agents only does not count it.
TEST(PackFile, OneAtForAgentsAndItemsIsALocation) {
  const char* shared_at = R"(
(define (domain yard)
  (:requirements :strips :typing)
  (:types locatable place - object agent item - locatable)
  (:predicates (at ?x - locatable ?p - place) (holding ?a - agent ?i - item))
  (:action move :parameters (?a - agent ?from ?to - place)
   :precondition (at ?a ?from) :effect (and (not (at ?a ?from)) (at ?a ?to)))
  (:action pickup :parameters (?a - agent ?i - item ?p - place)
   :precondition (and (at ?a ?p) (at ?i ?p)) :effect (and (not (at ?i ?p)) (holding ?a ?i)))
  (:action put :parameters (?a - agent ?i - item ?p - place)
   :precondition (and (at ?a ?p) (holding ?a ?i)) :effect (and (not (holding ?a ?i)) (at ?i ?p))))
)";
  const pddl::Domain d = pddl::parse_domain(shared_at, "yard.pddl");
  EXPECT_EQ(location_predicates(d, "agent"), (std::vector<std::string>{"at"}));
  PackSpec spec = parse_pack_spec(R"j({"domain": "yard", "language": {"salient_actions": [
      {"action": "pickup", "focal_arg": 2}, {"action": "put", "focal_arg": 2}]}})j", "yard/pack.json");
  derive_location_predicates(spec, d);
  EXPECT_EQ(spec.language.salient_actions[0].destination_arg, 0);
  EXPECT_EQ(spec.language.salient_actions[1].destination_arg, 3);
  // Where only agents are "at", items "in": only "in" is a location.
  const char* split = R"(
(define (domain yard2)
  (:requirements :strips :typing)
  (:types agent item place)
  (:predicates (at ?a - agent ?p - place) (in ?i - item ?p - place))
  (:action move :parameters (?a - agent ?from ?to - place)
   :precondition (at ?a ?from) :effect (and (not (at ?a ?from)) (at ?a ?to)))
  (:action drop :parameters (?a - agent ?i - item ?p - place)
   :precondition (at ?a ?p) :effect (in ?i ?p)))
)";
  EXPECT_EQ(location_predicates(pddl::parse_domain(split, "yard2.pddl"), "agent"), (std::vector<std::string>{"in"}));
}

TEST(PackFile, WithoutAFileTheGenericPackPlansAnything) {
  Pantry p;
  PackPtr pack = find_pack(*p.domain, p.dir.string());
  EXPECT_EQ(pack->spec().goals.source, GoalSource::ProblemGoal);
  auto task = data::ground_problem(*pack, p.domain, (p.dir / "p1.pddl").string());
  const auto goals = pack->problem_goals(*task, "p1.pddl");
  ASSERT_EQ(goals.size(), 1u);
  EXPECT_EQ(goals[0].condition, "(has cook apple)");
}

}  // namespace
}  // namespace clips::domains
