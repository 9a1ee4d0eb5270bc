#pragma once
// The includes, helpers and fixtures of the serve tests in pack_sessions_test.cpp, shared by
// the files of that name in tests/serve/ and its label folders
// (docs/testing.md, "Labels").
// Sessions on every pack, in process (no socket): the workshop (a text-scene
// pack with recorded plans), the kitchen of docs/domains.md served from a
// folder without any plan, sessions from PDDL text, the errors of text
// input, and the decision shown after undo and a method switch.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "language/listener.hpp"
#include "serve/kitchen_folder.hpp"
#include "serve/service.hpp"

namespace clips::serve {
namespace pack_sessions_test {

using nlohmann::json;

const std::string kExamples = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";
const std::string kWorkshop = std::string(CLIPS_SOURCE_DIR) + "/data/datasets/workshop";

std::shared_ptr<lm::LanguageModel> shared_lm() {
  static auto lm = language::make_language_model("embedded");
  return lm;
}

json body(const Reply& r) { return json::parse(r.body); }

std::string error_of(const Reply& r) { return body(r).value("error", ""); }

bool contains(const json& list, const std::string& s) {
  for (const auto& x : list)
    if (x == s) return true;
  return false;
}

const json* find_named(const json& list, const std::string& name) {
  for (const auto& x : list)
    if (x["name"] == name) return &x;
  return nullptr;
}

struct PackSessions : ::testing::Test {
  testing::KitchenFolder kitchen;
  std::unique_ptr<Service> make(ServiceLimits limits = {}) {
    return std::make_unique<Service>(std::vector<std::string>{kExamples, kWorkshop, kitchen.dir}, limits, shared_lm());
  }
  static json created(Service& s, const json& request) {
    Reply r = s.handle("POST", "/api/sessions", request.dump());
    EXPECT_EQ(r.status, 201) << r.body;
    return r.status == 201 ? body(r) : json::object();
  }
  static json post(Service& s, const std::string& url, const json& request, int status = 200) {
    Reply r = s.handle("POST", url, request.dump());
    EXPECT_EQ(r.status, status) << url << " " << request.dump() << ": " << r.body;
    return body(r);
  }
  // The kitchen's pack as a JSON object, without the file it names.
  json kitchen_pack() const {
    json pack = json::parse(testing::docs_example_files().at("kitchen/pack.json"));
    pack.erase("fewshot");
    return pack;
  }
};

// A study whose chest stands in a room by a fact no action changes, with
// books inside it, and a basket the human carries with a lamp in it (issue
// 62): the text scene draws the chest at its room with its contents, and the
// basket with its carrier, not as places of their own nor as loose facts.
const char* kStudyDomain = R"pddl(
(define (domain study)
  (:requirements :typing :negative-preconditions :equality)
  (:types agent item room chest colour - object  book lamp basket - item)
  (:predicates (at ?a - agent ?r - room) (in ?i - item ?r - room) (inside ?i - item ?c - object)
               (stands ?c - chest ?r - room) (holding ?a - agent ?i - item) (open ?c - chest)
               (iscolour ?i - item ?c - colour))
  (:action move :parameters (?a - agent ?from - room ?to - room)
   :precondition (and (at ?a ?from) (not (= ?from ?to))) :effect (and (not (at ?a ?from)) (at ?a ?to)))
  (:action open :parameters (?a - agent ?c - chest ?r - room)
   :precondition (and (at ?a ?r) (stands ?c ?r) (not (open ?c))) :effect (open ?c))
  (:action takeout :parameters (?a - agent ?i - item ?c - chest ?r - room)
   :precondition (and (at ?a ?r) (stands ?c ?r) (open ?c) (inside ?i ?c))
   :effect (and (not (inside ?i ?c)) (holding ?a ?i)))
  (:action handover :parameters (?a - agent ?b - agent ?i - item ?r - room)
   :precondition (and (not (= ?a ?b)) (at ?a ?r) (at ?b ?r) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (holding ?b ?i))))
)pddl";
const char* kStudyProblem = R"pddl(
(define (problem study-1) (:domain study)
  (:objects human robot - agent hall study - room chest1 - chest book1 book2 - book lamp1 - lamp
            basket1 - basket red blue - colour)
  (:init (at human hall) (at robot study) (stands chest1 study)
         (inside book1 chest1) (inside book2 chest1) (iscolour book1 red) (iscolour book2 blue)
         (holding human basket1) (inside lamp1 basket1)))
)pddl";
const char* kStudyPack = R"json({"domain": "study",
  "goals": {"source": "objects", "object_type": "book", "condition": "(holding human {})"},
  "language": {"salient_actions": [{"action": "takeout", "agent_arg": 1, "focal_arg": 2},
                                   {"action": "handover", "agent_arg": 1, "focal_arg": 3}],
               "qualifier": {"predicate": "iscolour"},
               "goal_atoms": {"takeout": ["(holding $1 $2)"], "handover": ["(holding $2 $3)"]}}})json";

}  // namespace pack_sessions_test
using namespace pack_sessions_test;
}  // namespace clips::serve
