#include "serve/pack_sessions_test.hpp"

namespace clips::serve {
namespace pack_sessions_test {
TEST_F(PackSessions, ListsEveryProblemWithItsPlansAndTheScene) {
  auto s = make();
  json j = body(s->handle("GET", "/api/datasets", ""));
  std::map<std::string, json> by_name;
  for (auto& d : j["datasets"]) by_name[d["name"]] = d;
  ASSERT_EQ(by_name.size(), 3u);
  EXPECT_EQ(by_name["doors-keys-gems"]["scene"], "grid");
  EXPECT_EQ(by_name["workshop"]["scene"], "text");
  EXPECT_EQ(by_name["workshop"]["problems"].size(), 8u);
  EXPECT_EQ(by_name["workshop"]["problems"][0]["id"], "1");
  EXPECT_FALSE(by_name["workshop"]["problems"][0]["plans"].empty());
  // The kitchen folder has problems and no plans at all.
  const json& kp = by_name["kitchen"]["problems"];
  ASSERT_EQ(kp.size(), 2u);
  EXPECT_EQ(kp[0]["id"], "1");
  EXPECT_EQ(kp[1]["id"], "2");
  EXPECT_TRUE(kp[0]["plans"].empty());
  EXPECT_EQ(j["limits"]["utterance_bytes"], 500);
}

TEST_F(PackSessions, WorkshopPlaysAsATextScene) {
  auto s = make();
  json st = created(*s, {{"dataset", "workshop"}, {"problem", "1"}});
  ASSERT_TRUE(st.contains("id"));
  const std::string url = "/api/sessions/" + st["id"].get<std::string>();
  EXPECT_EQ(st["plan"], "1.1.table");
  EXPECT_EQ(st["true_goal"], "table");
  EXPECT_EQ(st["noop_action"], "(wait human)");
  const json& sc = st["scene"];
  ASSERT_EQ(sc["kind"], "text");
  EXPECT_EQ(sc["active"], "human");
  // Places come from the atoms: agents are at stations, items lie on them.
  const json* rack = find_named(sc["places"], "rack");
  ASSERT_NE(rack, nullptr) << sc.dump();
  const json* plank1 = find_named((*rack)["objects"], "plank1");
  ASSERT_NE(plank1, nullptr);
  EXPECT_EQ((*plank1)["qualities"], json({"big", "wooden"}));
  EXPECT_NE(find_named(sc["places"], "bench"), nullptr);
  EXPECT_EQ(find_named(sc["places"], "plank1"), nullptr);  // an item is not a place
  EXPECT_EQ((*find_named(sc["agents"], "human"))["at"], "bench");
  EXPECT_TRUE(sc["changed"]["added"].empty());
  EXPECT_NE(sc["text"].get<std::string>().find("plank1 (big, wooden)"), std::string::npos);
  EXPECT_TRUE(contains(st["actions"], "(move human bench rack)")) << st["actions"].dump();

  st = post(*s, url + "/act", {{"action", "(move human bench rack)"}});
  EXPECT_EQ(st["turn"], "robot");
  EXPECT_TRUE(contains(st["scene"]["changed"]["added"], "(at human rack)")) << st["scene"]["changed"].dump();
  EXPECT_TRUE(contains(st["scene"]["changed"]["removed"], "(at human bench)"));
  EXPECT_TRUE(st["actions"].empty());  // the robot's turn
  json r = post(*s, url + "/assist", {{"apply", true}});
  EXPECT_NE(r["decision"]["action"].get<std::string>().find("robot"), std::string::npos);
  st = r["state"];
  ASSERT_EQ(st["turn"], "human");
  st = post(*s, url + "/act", {{"action", "(pickup human plank1 rack)"}});
  const json& human = *find_named(st["scene"]["agents"], "human");
  ASSERT_EQ(human["holds"].size(), 1u);
  EXPECT_EQ(human["holds"][0]["name"], "plank1");
  EXPECT_EQ(find_named((*find_named(st["scene"]["places"], "rack"))["objects"], "plank1"), nullptr);
  st = post(*s, url + "/assist", {{"apply", true}})["state"];
  st = post(*s, url + "/hear", {{"utterance", "Could you grab the big one for me?"}});
  ASSERT_FALSE(st["reading"].is_null());
  EXPECT_FALSE(st["reading"]["commands"].empty());
  double sum = 0;
  for (auto& g : st["posterior"]["goals"]) sum += g["p"].get<double>();
  EXPECT_NEAR(sum, 1.0, 1e-9);
}

TEST_F(PackSessions, AProblemWithoutARecordedPlanPlays) {
  auto s = make();
  json st = created(*s, {{"dataset", "kitchen"}, {"problem", "2"}});
  ASSERT_TRUE(st.contains("id"));
  const std::string url = "/api/sessions/" + st["id"].get<std::string>();
  EXPECT_TRUE(st["plan"].is_null());
  EXPECT_TRUE(st["true_goal"].is_null());
  EXPECT_TRUE(st["observed_moves"].empty());
  // The pack's goal rule: one goal per dish.
  std::vector<std::string> goals;
  for (auto& g : st["posterior"]["goals"]) goals.push_back(g["goal"]);
  EXPECT_EQ(goals, (std::vector<std::string>{"cake", "cookies", "fudge", "pudding"}));
  EXPECT_EQ(st["turn"], "cook");
  EXPECT_EQ(st["scene"]["kind"], "text");
  EXPECT_EQ((*find_named(st["scene"]["agents"], "helper"))["at"], "pantry");
  st = post(*s, url + "/act", {{"action", "(move cook counter fridge)"}});
  st = post(*s, url + "/assist", {{"apply", true}})["state"];
  EXPECT_EQ(st["turn"], "cook");
  st = post(*s, url + "/hear", {{"utterance", "Can you fetch the sugar?"}});
  EXPECT_FALSE(st["reading"].is_null());
  EXPECT_NE(post(*s, url + "/assist", {{"apply", false}}, 409)["error"].get<std::string>().find("turn"), std::string::npos);
  // Problem 1 of the same folder has no plan either, and plays the same way.
  st = created(*s, {{"dataset", "kitchen"}, {"problem", "1"}});
  EXPECT_TRUE(st["plan"].is_null());
  // A problem that is not in the folder, or a plan that does not exist, is a 400 naming the field.
  Reply r = s->handle("POST", "/api/sessions", R"j({"dataset":"kitchen","problem":"3"})j");
  EXPECT_EQ(r.status, 400);
  EXPECT_NE(error_of(r).find("field 'problem'"), std::string::npos) << r.body;
  EXPECT_NE(error_of(r).find("problems: 1, 2"), std::string::npos) << r.body;
  r = s->handle("POST", "/api/sessions", R"j({"dataset":"kitchen","problem":"2","plan":"2.1.cake"})j");
  EXPECT_EQ(r.status, 400);
  EXPECT_NE(error_of(r).find("field 'plan'"), std::string::npos) << r.body;
}

TEST_F(PackSessions, SessionFromPddlText) {
  auto s = make();
  const auto files = testing::docs_example_files();
  json st = created(*s, {{"domain", files.at("kitchen/domain.pddl")},
                         {"problem", files.at("kitchen/problems/1.pddl")},
                         {"pack", kitchen_pack()}});
  ASSERT_TRUE(st.contains("id"));
  const std::string url = "/api/sessions/" + st["id"].get<std::string>();
  EXPECT_TRUE(st["dataset"].is_null());
  EXPECT_EQ(st["domain"], "kitchen");
  EXPECT_EQ(st["problem"], "kitchen-1");
  EXPECT_EQ(st["posterior"]["goals"].size(), 4u);
  EXPECT_EQ(st["scene"]["kind"], "text");
  st = post(*s, url + "/act", {{"action", "(take cook flour1 pantry)"}});
  st = post(*s, url + "/hear", {{"utterance", "Can you fetch the milk?"}});
  json r = post(*s, url + "/assist", {{"apply", true}});
  EXPECT_NE(r["decision"]["action"].get<std::string>().find("helper"), std::string::npos);
  // The pack may also come as a string holding the JSON.
  st = created(*s, {{"domain", files.at("kitchen/domain.pddl")},
                    {"problem", testing::kitchen_problem_2()},
                    {"pack", kitchen_pack().dump()}});
  EXPECT_EQ(st["problem"], "kitchen-2");
}

TEST_F(PackSessions, BadTextInputIsA400NamingTheField) {
  ServiceLimits limits;
  limits.max_pddl_bytes = 4000;
  auto s = make(limits);
  const auto files = testing::docs_example_files();
  const std::string domain = files.at("kitchen/domain.pddl"), problem = files.at("kitchen/problems/1.pddl");
  const json pack = kitchen_pack();
  auto expect_400 = [&](const json& request, const std::string& field, const std::string& also = "") {
    Reply r = s->handle("POST", "/api/sessions", request.dump());
    EXPECT_EQ(r.status, 400) << request.dump().substr(0, 200) << ": " << r.body;
    EXPECT_NE(error_of(r).find("field '" + field + "'"), std::string::npos) << r.body;
    if (!also.empty()) {
      EXPECT_NE(error_of(r).find(also), std::string::npos) << r.body;
    }
  };
  expect_400({{"domain", "(define (domain kitchen"}, {"problem", problem}, {"pack", pack}}, "domain");
  expect_400({{"domain", "(define (domain kitchen) (:types a - b) (:predicates (p ?x - nope)))"}, {"problem", problem}},
             "domain", "nope");
  expect_400({{"domain", domain}, {"problem", "(define (problem p) (:domain kitchen) (:objects x - plank))"},
              {"pack", pack}},
             "problem", "plank");
  expect_400({{"domain", domain}, {"problem", "not pddl at all"}, {"pack", pack}}, "problem");
  expect_400({{"domain", domain}, {"problem", problem}, {"pack", "{"}}, "pack");
  expect_400({{"domain", domain}, {"problem", problem}, {"pack", 12}}, "pack");
  expect_400({{"domain", domain}, {"problem", problem}, {"pack", json::parse(files.at("kitchen/pack.json"))}}, "pack",
             "may not name files");
  json wrong = pack;
  wrong["roles"]["principal"] = "chef";
  expect_400({{"domain", domain}, {"problem", problem}, {"pack", wrong}}, "problem", "chef");
  // Without a pack the generic one plays "human" and "robot", which the kitchen lacks.
  expect_400({{"domain", domain}, {"problem", problem}}, "problem", "human");
  expect_400({{"domain", std::string(4001, ' ')}, {"problem", problem}}, "domain", "limit of 4000");
  expect_400({{"domain", domain}, {"problem", std::string(4001, '(')}}, "problem", "limit of 4000");
  expect_400({{"domain", domain}, {"problem", problem}, {"dataset", "kitchen"}}, "dataset");
  expect_400({{"domain", domain}, {"problem", problem}, {"plan", "1.1.cake"}}, "plan");
  expect_400({{"domain", domain}}, "problem", "required");
  expect_400({{"dataset", "kitchen"}, {"problem", "1"}, {"pack", pack}}, "pack");
  expect_400({{"problem", "1"}}, "dataset", "required");
  // Grounding is bounded: six parameters over 20 objects are 64 million actions.
  std::string objects;
  for (int i = 0; i < 20; ++i) objects += " o" + std::to_string(i);
  expect_400({{"domain", "(define (domain big) (:predicates (p ?a ?b ?c ?d ?e ?f)) (:action go :parameters (?a ?b ?c "
                         "?d ?e ?f) :precondition (and) :effect (p ?a ?b ?c ?d ?e ?f)))"},
              {"problem", "(define (problem big1) (:domain big) (:objects human robot" + objects + ") (:init) (:goal (p o1 o1 o1 o1 o1 o1)))"}},
             "problem", "go");
  // Every cut of a valid text is a clear error, never a server fault.
  for (size_t cut = 1; cut < domain.size(); cut += 97) {
    Reply r = s->handle("POST", "/api/sessions", json{{"domain", domain.substr(0, cut)}, {"problem", problem}, {"pack", pack}}.dump());
    EXPECT_EQ(r.status, 400) << cut << ": " << r.body;
  }
  for (size_t cut = 1; cut < problem.size(); cut += 61) {
    Reply r = s->handle("POST", "/api/sessions", json{{"domain", domain}, {"problem", problem.substr(0, cut)}, {"pack", pack}}.dump());
    EXPECT_EQ(r.status, 400) << cut << ": " << r.body;
  }
  EXPECT_EQ(s->live_sessions(), 0u);
}

TEST_F(PackSessions, TheDecisionShownIsTheLatestStillInTheHistory) {
  auto s = make();
  json st = created(*s, {{"dataset", "doors-keys-gems"}, {"problem", "e1"}, {"plan", "e1.1.keys"}});
  const std::string url = "/api/sessions/" + st["id"].get<std::string>();
  EXPECT_TRUE(st["decision"].is_null());
  post(*s, url + "/act", {{"action", "(left human)"}});
  const json first = post(*s, url + "/assist", {{"apply", true}})["decision"];
  EXPECT_EQ(first["t"], 1);
  post(*s, url + "/act", {{"action", "(left human)"}});
  st = post(*s, url + "/assist", {{"apply", true}})["state"];
  EXPECT_EQ(st["decision"]["t"], 3);
  // Undo takes back the second move and its reply: the first decision is shown again.
  st = post(*s, url + "/undo", json::object());
  EXPECT_EQ(st["t"], 2);
  EXPECT_EQ(st["decision"], first);
  // A method switch keeps it, naming the method that made it.
  st = post(*s, url + "/method", {{"method", "lang_only"}});
  EXPECT_EQ(st["method"], "lang_only");
  EXPECT_EQ(st["decision"]["method"], "clips");
  EXPECT_EQ(st["decision"], first);
  // A decision not taken is shown until something happens.
  post(*s, url + "/act", {{"action", "(left human)"}});
  const json preview = post(*s, url + "/assist", {{"apply", false}})["decision"];
  st = body(s->handle("GET", url, ""));
  EXPECT_EQ(st["decision"], preview);
  EXPECT_EQ(st["decision"]["applied"], false);
  st = post(*s, url + "/act", {{"action", "(wait robot)"}});
  EXPECT_EQ(st["decision"], first);
  st = post(*s, url + "/reset", json::object());
  EXPECT_TRUE(st["decision"].is_null());
}

TEST_F(PackSessions, TextSceneDrawsThingsInTheirHoldersAndCarriers) {
  auto s = make();
  json st = created(*s, {{"domain", kStudyDomain}, {"problem", kStudyProblem}, {"pack", kStudyPack}});
  ASSERT_TRUE(st.contains("id"));
  const json& sc = st["scene"];
  ASSERT_EQ(sc["kind"], "text");
  // Places are where agents stand: the rooms, not the chest nor the basket.
  std::vector<std::string> places;
  for (const auto& p : sc["places"]) places.push_back(p["name"]);
  EXPECT_EQ(places, (std::vector<std::string>{"hall", "study"})) << sc.dump();
  // The chest stands in the study, the books inside it.
  const json* study = find_named(sc["places"], "study");
  ASSERT_NE(study, nullptr);
  const json* chest = find_named((*study)["objects"], "chest1");
  ASSERT_NE(chest, nullptr) << sc.dump();
  ASSERT_TRUE(chest->contains("contents")) << chest->dump();
  const json* book1 = find_named((*chest)["contents"], "book1");
  ASSERT_NE(book1, nullptr) << chest->dump();
  EXPECT_EQ((*book1)["relation"], "inside");
  EXPECT_EQ((*book1)["qualities"], json({"red"}));
  EXPECT_NE(find_named((*chest)["contents"], "book2"), nullptr);
  EXPECT_FALSE(chest->contains("states"));  // closed: (open chest1) is false
  // The basket is carried by the human, with the lamp in it.
  const json& human = *find_named(sc["agents"], "human");
  ASSERT_EQ(human["holds"].size(), 1u) << human.dump();
  EXPECT_EQ(human["holds"][0]["name"], "basket1");
  ASSERT_EQ(human["holds"][0]["contents"].size(), 1u);
  EXPECT_EQ(human["holds"][0]["contents"][0]["name"], "lamp1");
  // Nothing of it is left to the facts, nor drawn on its own.
  EXPECT_TRUE(sc["facts"].empty()) << sc["facts"].dump();
  EXPECT_TRUE(sc["others"].empty());
  EXPECT_NE(sc["text"].get<std::string>().find("chest1 [inside: book1 (red), book2 (blue)]"), std::string::npos)
      << sc["text"];
  // Opened, the chest says so beside it, not among the facts.
  const std::string url = "/api/sessions/" + st["id"].get<std::string>();
  st = post(*s, url + "/act", {{"action", "(move human hall study)"}});
  st = post(*s, url + "/act", {{"action", "(open robot chest1 study)"}});
  chest = find_named((*find_named(st["scene"]["places"], "study"))["objects"], "chest1");
  ASSERT_NE(chest, nullptr);
  EXPECT_EQ((*chest)["states"], json({"open"})) << chest->dump();
  EXPECT_TRUE(st["scene"]["facts"].empty()) << st["scene"]["facts"].dump();
  // Taken out, the book is with its carrier.
  st = post(*s, url + "/act", {{"action", "(takeout human book1 chest1 study)"}});
  const json& holds = (*find_named(st["scene"]["agents"], "human"))["holds"];
  EXPECT_NE(find_named(holds, "book1"), nullptr) << holds.dump();
  chest = find_named((*find_named(st["scene"]["places"], "study"))["objects"], "chest1");
  EXPECT_EQ(find_named((*chest)["contents"], "book1"), nullptr);
}

// Each reading comes in parts a front end says in words: the acting agent
// (pronouns become the pack's agents), the action's name as words and its
// objects with their nouns and qualities; the PDDL form stays beside them.
TEST_F(PackSessions, ReadingsComeInPartsForWords) {
  auto s = make();
  json st = created(*s, {{"domain", kStudyDomain}, {"problem", kStudyProblem}, {"pack", kStudyPack}});
  const std::string url = "/api/sessions/" + st["id"].get<std::string>();
  st = post(*s, url + "/act", {{"action", "(move human hall study)"}});
  st = post(*s, url + "/assist", {{"apply", true}})["state"];
  st = post(*s, url + "/hear", {{"utterance", "Could you hand me the red book?"}});
  ASSERT_FALSE(st["reading"].is_null());
  const json& cmds = st["reading"]["commands"];
  ASSERT_FALSE(cmds.empty());
  bool handover_seen = false;
  for (const auto& c : cmds) {
    const std::string pddl = c["command"];
    ASSERT_TRUE(c.contains("steps")) << c.dump();
    if (pddl.rfind("(no command", 0) == 0) {
      EXPECT_TRUE(c["steps"].empty());
      continue;
    }
    // A goal statement names its goal by label; its (make ...) is no step.
    if (c.contains("goal")) {
      EXPECT_TRUE(c["goal"] == "book1" || c["goal"] == "book2") << c.dump();
      for (const auto& step : c["steps"]) EXPECT_NE(step["action"], "make");
    }
    for (const auto& step : c["steps"]) {
      EXPECT_TRUE(step["agent"] == "robot" || step["agent"] == "human") << step.dump();
      EXPECT_NE(pddl.find("(" + step["action"].get<std::string>() + " "), std::string::npos) << pddl;
      if (step["action"] != "handover") continue;
      handover_seen = true;
      EXPECT_EQ(step["verb"], "hand over");  // the run-together name split into words
      // (handover you me ?book1) where (iscolour ?book1 red): to the human, the red book.
      ASSERT_EQ(step["objects"].size(), 2u) << step.dump();
      EXPECT_EQ(step["objects"][0]["name"], "human");
      const json& book = step["objects"][1];
      if (book["name"].get<std::string>().front() == '?') {
        EXPECT_EQ(book["noun"], "book");
        if (pddl.find("iscolour " + book["name"].get<std::string>() + " red") != std::string::npos) {
          EXPECT_EQ(book["qualities"], json({"red"})) << pddl;
        }
      }
    }
  }
  EXPECT_TRUE(handover_seen) << cmds.dump();
}

}  // namespace pack_sessions_test

}  // namespace clips::serve
