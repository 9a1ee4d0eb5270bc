// Task transformations (domains/task_transform.hpp): what clips adds to a
// domain without the turn idiom or `frozen`, that domains with them are left
// exactly as parsed, and the errors that name the action or the pack field.
#include "domains/builtin/packs.hpp"
#include "domains/task_transform.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "data/dataset.hpp"
#include "model/spec.hpp"
#include "pddl/parser.hpp"
#include "util/error.hpp"

namespace clips::domains {
namespace {

namespace fs = std::filesystem;

// An ordinary two-agent domain: no turns, no frozen, no no-op.
constexpr const char* kPassDomain = R"((define (domain pass)
  (:requirements :typing)
  (:types person bot - agent thing place - object)
  (:predicates (at ?a - agent ?p - place) (has ?a - agent ?t - thing) (on ?t - thing ?p - place))
  (:action go :parameters (?a - agent ?from - place ?to - place)
    :precondition (at ?a ?from) :effect (and (not (at ?a ?from)) (at ?a ?to)))
  (:action grab :parameters (?a - agent ?t - thing ?p - place)
    :precondition (and (at ?a ?p) (on ?t ?p)) :effect (and (has ?a ?t) (not (on ?t ?p))))))";
constexpr const char* kPassProblem = R"((define (problem p1) (:domain pass)
  (:objects ann - person rob - bot hall room - place cup - thing)
  (:init (at ann hall) (at rob room) (on cup room))))";

// A folder with a domain, one problem and a pack; removed on destruction.
struct Folder {
  explicit Folder(const std::string& domain, const std::string& pack, const std::string& problem = kPassProblem) {
    std::random_device rd;
    dir = fs::temp_directory_path() / ("clips-transform-test-" + std::to_string(rd()));
    fs::create_directories(dir);
    std::ofstream(dir / "domain.pddl") << domain;
    std::ofstream(dir / "p1.pddl") << problem;
    if (!pack.empty()) std::ofstream(dir / "pack.json") << pack;
  }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  DomainWithPack load() const { return load_domain_with_pack((dir / "domain.pddl").string(), dir.string()); }
  std::shared_ptr<const pddl::Task> task() const {
    auto [domain, pack] = load();
    return data::ground_problem(*pack, domain, (dir / "p1.pddl").string());
  }
  fs::path dir;
};

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool applicable(const pddl::Task& t, const pddl::State& s, const std::string& action) {
  const auto a = t.find_action(action);
  return a && t.applicable(*a, s.data());
}

pddl::State apply(const pddl::Task& t, const pddl::State& s, const std::string& action) {
  const auto a = t.find_action(action);
  EXPECT_TRUE(a && t.applicable(*a, s.data())) << action;
  return a ? t.apply(s, *a) : s;
}

TEST(TaskTransform, AlternatingTurnsTheNoOpAndFreezingAreAdded) {
  Folder f(kPassDomain, R"j({"domain": "pass", "roles": {"principal": "ann", "assistant": "rob"}})j");
  const auto [domain, pack] = f.load();
  const TaskTransform& t = pack->spec().transform;
  EXPECT_TRUE(t.compile_turns && t.add_noop && t.add_frozen);
  EXPECT_EQ(t.turn_order, (std::vector<std::string>{"ann", "rob"}));
  for (const char* p : {"active", "next-turn", "frozen"}) EXPECT_TRUE(domain->find_predicate(p)) << p;
  EXPECT_GE(domain->find_action("wait"), 0);

  auto task = f.task();
  const model::TurnTaking& turns = pack->roles();
  pddl::State s = task->initial_state();
  EXPECT_TRUE(turns.is_turn_of(*task, s, "ann"));
  EXPECT_EQ(turns.active_agent(*task, s), "ann");
  EXPECT_FALSE(applicable(*task, s, "(grab rob cup room)"));  // not rob's turn
  EXPECT_NE(task->explain_inapplicable(task->action(*task->find_action("(grab rob cup room)")).schema,
                                       task->action(*task->find_action("(grab rob cup room)")).args, s)
                .find("(active rob)"),
            std::string::npos);
  EXPECT_EQ(task->action_name(turns.noop(*task, "ann")), "(wait ann)");
  s = apply(*task, s, "(go ann hall room)");
  EXPECT_EQ(turns.active_agent(*task, s), "rob");
  s = apply(*task, s, "(grab rob cup room)");
  EXPECT_EQ(turns.active_agent(*task, s), "ann");
  // Frozen: ann may only wait.
  const pddl::State frozen = model::freeze(*task, s, "ann");
  EXPECT_FALSE(applicable(*task, frozen, "(go ann room hall)"));
  EXPECT_TRUE(applicable(*task, frozen, "(wait ann)"));
  // A dataset plan in turn order simulates; one out of turn names the step.
  pddl::PlanFile plan;
  plan.actions = {{"(go ann hall room)", {"plan", 1, 1}}, {"(wait rob)", {"plan", 2, 1}}, {"(grab ann cup room)", {"plan", 3, 1}}};
  EXPECT_EQ(pddl::simulate(*task, task->initial_state(), plan).actions.size(), 3u);
  plan.actions.erase(plan.actions.begin() + 1);
  EXPECT_THROW(pddl::simulate(*task, task->initial_state(), plan), InputError);
}

TEST(TaskTransform, AnExplicitTurnOrderStartsWithItsFirstAgent) {
  Folder f(kPassDomain, R"j({"domain": "pass", "roles": {"principal": "ann", "assistant": "rob", "turns": ["rob", "ann"]}})j");
  auto task = f.task();
  EXPECT_EQ(f.load().pack->roles().active_agent(*task, task->initial_state()), "rob");
  EXPECT_TRUE(applicable(*task, task->initial_state(), "(grab rob cup room)"));
}

TEST(TaskTransform, TheNoOpAndTurnPredicateAreThePacks) {
  Folder f(kPassDomain, R"j({"domain": "pass", "roles": {"principal": "ann", "assistant": "rob", "noop_action": "idle",
                                                      "turn_predicate": "turn"}})j");
  auto [domain, pack] = f.load();
  EXPECT_TRUE(domain->find_predicate("turn"));
  EXPECT_FALSE(domain->find_predicate("active"));
  EXPECT_LT(domain->find_action("wait"), 0);
  auto task = f.task();
  EXPECT_EQ(task->action_name(pack->roles().noop(*task, "rob")), "(idle rob)");
  EXPECT_TRUE(pack->roles().is_turn_of(*task, task->initial_state(), "ann"));
  EXPECT_TRUE(task->atom("turn", {"ann"}).bit >= 0);
}

TEST(TaskTransform, DomainsWithTheIdiomAreLeftAsParsed) {
  // The workshop writes the turn idiom and frozen: nothing is added, and the
  // prepared domain is the parsed one itself.
  const std::string dir = CLIPS_SOURCE_DIR "/data/datasets/workshop";
  auto parsed = std::make_shared<const pddl::Domain>(pddl::load_domain(dir + "/domain.pddl"));
  PackPtr pack = find_pack(*parsed, dir);
  EXPECT_TRUE(pack->spec().transform.empty());
  EXPECT_EQ(prepare_domain(pack->spec(), parsed).get(), parsed.get());
  auto d = std::make_shared<const pddl::Domain>(pddl::load_domain(CLIPS_SOURCE_DIR "/data/domains/doors-keys-gems/domain.pddl"));
  PackPtr p = find_pack(*d, "");
  EXPECT_TRUE(p->spec().transform.empty());
  EXPECT_EQ(prepare_domain(p->spec(), d).get(), d.get());
}

TEST(TaskTransform, ADomainWithTurnsButNoFrozenGetsFrozenAfterItsTurnAtom) {
  const std::string domain = R"((define (domain turns)
  (:requirements :typing :negative-preconditions :conditional-effects)
  (:types person bot - agent place - object)
  (:predicates (at ?a - agent ?p - place) (active ?a - agent) (next-turn ?a - agent ?b - agent))
  (:action go :parameters (?a - agent ?from - place ?to - place)
    :precondition (and (active ?a) (at ?a ?from))
    :effect (and (not (at ?a ?from)) (at ?a ?to) (not (active ?a))
                 (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))
  (:action wait :parameters (?a - agent) :precondition (active ?a)
    :effect (and (not (active ?a)) (forall (?b - agent) (when (next-turn ?a ?b) (active ?b)))))))";
  const std::string problem = R"((define (problem p1) (:domain turns)
  (:objects ann - person rob - bot hall room - place)
  (:init (at ann hall) (at rob room) (active ann) (next-turn ann rob) (next-turn rob ann))))";
  Folder f(domain, R"j({"domain": "turns", "roles": {"principal": "ann", "assistant": "rob"}})j", problem);
  auto [d, pack] = f.load();
  EXPECT_FALSE(pack->spec().transform.compile_turns);
  EXPECT_TRUE(pack->spec().transform.add_frozen);
  const auto& go = d->actions[static_cast<size_t>(d->find_action("go"))];
  ASSERT_EQ(go.precondition->kind, pddl::Condition::Kind::And);
  EXPECT_EQ(go.precondition->kids[1].kind, pddl::Condition::Kind::Not);  // (and (active ?a) (not (frozen ?a)) ...)
  auto task = f.task();
  const pddl::State frozen = model::freeze(*task, task->initial_state(), "ann");
  EXPECT_FALSE(applicable(*task, frozen, "(go ann hall room)"));
  EXPECT_TRUE(applicable(*task, frozen, "(wait ann)"));
}

TEST(TaskTransform, ErrorsNameTheActionOrTheField) {
  // The acting agent must come first.
  const std::string swapped = std::string(kPassDomain).replace(std::string(kPassDomain).rfind(")))"), 3,
      "))\n  (:action drop :parameters (?t - thing ?a - agent ?p - place)\n"
      "    :precondition (has ?a ?t) :effect (and (on ?t ?p) (not (has ?a ?t)))))");
  const std::string pack = R"j({"domain": "pass", "roles": {"principal": "ann", "assistant": "rob"}})j";
  std::string e = error_of([&] { Folder(swapped, pack).load(); });
  EXPECT_NE(e.find("action 'drop'"), std::string::npos) << e;
  EXPECT_NE(e.find("move ?a to the front"), std::string::npos) << e;
  EXPECT_NE(e.find("domain.pddl:"), std::string::npos) << e;
  // No agents' type.
  e = error_of([&] {
    Folder(kPassDomain, R"j({"domain": "pass", "roles": {"principal": "ann", "assistant": "rob", "agent_type": "robot"}})j").load();
  });
  EXPECT_NE(e.find("roles.agent_type"), std::string::npos) << e;
  // "domain" turns need the domain's turn predicate.
  e = error_of([&] {
    Folder(kPassDomain, R"j({"domain": "pass", "roles": {"principal": "ann", "assistant": "rob", "turns": "domain"}})j").load();
  });
  EXPECT_NE(e.find("roles.turns"), std::string::npos) << e;
  // The roles name objects of each problem.
  e = error_of([&] { Folder(kPassDomain, R"j({"domain": "pass", "roles": {"principal": "ann"}})j").task(); });
  EXPECT_NE(e.find("roles.assistant names 'robot'"), std::string::npos) << e;
  EXPECT_NE(e.find("p1.pddl"), std::string::npos) << e;
  // An explicit order names agents.
  e = error_of([&] {
    Folder(kPassDomain, R"j({"domain": "pass", "roles": {"principal": "ann", "assistant": "rob", "turns": ["ann", "rob", "cup"]}})j")
        .task();
  });
  EXPECT_NE(e.find("roles.turns[2]"), std::string::npos) << e;
  EXPECT_NE(e.find("not of the agents' type"), std::string::npos) << e;
  // A problem may not state the compiled turn facts.
  const std::string stated = std::string(kPassProblem).replace(std::string(kPassProblem).find("(on cup room)"), 13,
                                                               "(on cup room) (active rob)");
  e = error_of([&] { Folder(kPassDomain, pack, stated).task(); });
  EXPECT_NE(e.find("leave the turn facts out"), std::string::npos) << e;
  // The no-op takes the agent only.
  const std::string noop = std::string(kPassDomain).replace(std::string(kPassDomain).rfind(")))"), 3,
      "))\n  (:action wait :parameters (?a - agent ?p - place) :precondition (at ?a ?p) :effect (and)))");
  e = error_of([&] { Folder(noop, pack).load(); });
  EXPECT_NE(e.find("roles.noop_action"), std::string::npos) << e;
}

TEST(TaskTransform, OnlyTheAgentsTypeMayBeAnUndeclaredParent) {
  // kPassDomain never declares `agent` itself: that passes, with a pack or without.
  const std::string pack = R"j({"domain": "pass", "roles": {"principal": "ann", "assistant": "rob"}})j";
  EXPECT_EQ(error_of([&] { Folder(kPassDomain, pack).load(); }), "");
  EXPECT_EQ(error_of([&] { Folder(kPassDomain, "").load(); }), "");
  // A slip in another parent's name is refused where it is written.
  const std::string slip = std::string(kPassDomain).replace(std::string(kPassDomain).find("thing place - object"), 20,
                                                            "thing - thngs place - object");
  for (const std::string& p : {pack, std::string()}) {
    const std::string e = error_of([&] { Folder(slip, p).load(); });
    EXPECT_NE(e.find("domain.pddl:3:"), std::string::npos) << e;
    EXPECT_NE(e.find("type 'thngs' is named as a parent but never declared"), std::string::npos) << e;
  }
  // Declared, it passes.
  const std::string declared = std::string(slip).replace(slip.find("place - object"), 14, "place thngs - object");
  EXPECT_EQ(error_of([&] { Folder(declared, pack).load(); }), "");
}

TEST(TaskTransform, TheGenericPackAddsNothing) {
  Folder f(kPassDomain, "");
  auto [domain, pack] = f.load();
  EXPECT_TRUE(pack->spec().generic);
  EXPECT_FALSE(domain->find_predicate("active"));
  EXPECT_FALSE(domain->find_predicate("frozen"));
}

}  // namespace
}  // namespace clips::domains
