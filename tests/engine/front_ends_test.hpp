#pragma once
// The includes, helpers and fixtures of the engine tests in front_ends_test.cpp, shared by
// the files of that name in tests/engine/ and its label folders
// (docs/testing.md, "Labels").
// One plan through every front end of the session engine: the CLI (`clips
// infer --json`, `clips assist --json`), the C++ session API, Python and the
// server's request handlers (as `clips serve --stdio` answers them) give the
// same posteriors step by step and the same decision.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "clips/clips.hpp"
#include "data/dataset.hpp"
#include "engine/json.hpp"
#include "language/listener.hpp"
#include "serve/service.hpp"
#include "run_command.hpp"
#include "test_paths.hpp"

namespace front_ends_test {

using nlohmann::json;

const std::string kDataset = clips::paths::examples_dir() + "/doors-keys-gems";
const std::vector<std::string> kActions = {"(left human)", "(wait robot)", "(left human)"};
const std::string kUtterance = "Can you get me the yellow key?";

using clips::tests::stdout_of;

std::string cli_observations() {
  std::string actions;
  for (const auto& a : kActions) actions += (actions.empty() ? "" : " ") + a;
  return " --dataset " + kDataset + " --problem e1 --actions '" + actions + "' --utterance '" + kUtterance +
         "' --utterance-step " + std::to_string(kActions.size());
}

void expect_near_all(const std::vector<double>& a, const std::vector<double>& b, const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-9) << where << " [" << i << "]";
}

// What every front end reports: the goal posterior after each step (the last
// one with the utterance heard), and the decision then.
struct FrontEndRun {
  std::vector<std::vector<double>> steps;
  std::vector<std::string> goals;
  std::string action;
  std::vector<std::pair<std::string, double>> candidates;
  json posterior;  // the final posterior in JSON, as this front end writes it
};

// The same JSON shape (keys, array lengths, strings, nulls) with numbers
// within 1e-9: the one serializer (engine/json.hpp) behind every front end.
void expect_same_json(const json& a, const json& b, const std::string& where) {
  if (a.is_number() && b.is_number()) {
    EXPECT_NEAR(a.get<double>(), b.get<double>(), 1e-9) << where;
    return;
  }
  ASSERT_EQ(a.type(), b.type()) << where << ": " << a << " vs " << b;
  if (a.is_object()) {
    ASSERT_EQ(a.size(), b.size()) << where << ": " << a << " vs " << b;
    for (const auto& [k, v] : a.items()) {
      ASSERT_TRUE(b.contains(k)) << where << ": no " << k;
      expect_same_json(v, b[k], where + "." + k);
    }
  } else if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << where;
    for (size_t i = 0; i < a.size(); ++i) expect_same_json(a[i], b[i], where + "[" + std::to_string(i) + "]");
  } else {
    EXPECT_EQ(a, b) << where;
  }
}

FrontEndRun session_run() {
  auto s = clips::Session::open_dataset(kDataset, "e1");
  for (const auto& a : kActions) s.observe(a);
  s.hear(kUtterance);
  FrontEndRun r;
  for (const auto& st : s.trace()) r.steps.push_back(st.posterior.goal_probabilities);
  r.goals = s.posterior().goals;
  r.posterior = clips::engine::to_json(s.posterior(), clips::Method::Clips);  // the session's default method
  const auto d = s.assist();
  r.action = d.action;
  for (const auto& c : d.candidates) r.candidates.push_back({c.action, c.value});
  return r;
}

FrontEndRun cli_run() {
  const std::string clips = std::string(CLIPS_BINARY_DIR) + "/clips";
  const json infer = json::parse(stdout_of(clips + " infer --json" + cli_observations()));
  const json assist = json::parse(stdout_of(clips + " assist --json" + cli_observations()));
  FrontEndRun r;
  for (const auto& st : infer["steps"]) {
    std::vector<double> p;  // the engine's posterior JSON, as the server's below
    for (const auto& g : st["posterior"]["goals"]) p.push_back(g["p"]);
    r.steps.push_back(std::move(p));
  }
  r.goals = infer["goals"].get<std::vector<std::string>>();
  r.posterior = infer["steps"].back()["posterior"];
  expect_same_json(r.posterior, assist["posterior"], "infer --json vs assist --json posterior");
  // The engine's JSON of the decision.
  EXPECT_EQ(assist["decision"]["method"], "clips");
  r.action = assist["decision"]["action"].get<std::string>();
  for (const auto& c : assist["decision"]["candidates"]) r.candidates.push_back({c["action"], c["value"]});
  std::vector<double> last;
  for (const auto& g : assist["posterior"]["goals"]) last.push_back(g["p"]);
  expect_near_all(last, r.steps.back(), "assist --json posterior");
  return r;
}

FrontEndRun server_run() {
  auto lm = clips::language::make_language_model("embedded");
  clips::serve::Service service({kDataset}, {}, lm);
  auto call = [&](const std::string& method, const std::string& path, const json& body) {
    const auto reply = service.handle(method, path, body.is_null() ? "" : body.dump());
    EXPECT_LT(reply.status, 300) << path << ": " << reply.body;
    return json::parse(reply.body);
  };
  const json created = call("POST", "/api/sessions", {{"dataset", "doors-keys-gems"}, {"problem", "e1"}});
  const std::string id = created["id"];
  for (const auto& a : kActions) call("POST", "/api/sessions/" + id + "/act", {{"action", a}});
  const json state = call("POST", "/api/sessions/" + id + "/hear", {{"utterance", kUtterance}});
  FrontEndRun r;
  // One history point per update: the start, each action, the utterance.
  const auto& history = state["history"];
  EXPECT_EQ(history.size(), kActions.size() + 2);
  for (size_t i = 0; i < history.size(); ++i)
    if (i != kActions.size()) r.steps.push_back(history[i]["goals"].get<std::vector<double>>());
  for (const auto& g : state["posterior"]["goals"]) r.goals.push_back(g["goal"]);
  EXPECT_TRUE(state["posterior"].contains("log_marginal_likelihood"));
  r.posterior = state["posterior"];
  // The server adds each goal's colour for the play page; the rest is the engine's JSON.
  for (auto& g : r.posterior["goals"]) EXPECT_EQ(g.erase("colour"), 1u);
  const json d = call("POST", "/api/sessions/" + id + "/assist", {{"apply", false}})["decision"];
  r.action = d["action"];
  for (const auto& c : d["candidates"]) r.candidates.push_back({c["action"], c["value"]});
  return r;
}

FrontEndRun python_run() {
  const std::string script = std::string(CLIPS_BINARY_DIR) + "/front_ends_test.py";
  {
    std::string actions;
    for (const auto& a : kActions) actions += "\"" + a + "\", ";
    std::ofstream f(script);
    f << "import json, clips_assist\n"
      << "s = clips_assist.Session.open_dataset(\"" << kDataset << "\", \"e1\")\n"
      << "for a in [" << actions << "]:\n    s.observe(a)\n"
      << "s.hear(\"" << kUtterance << "\")\n"
      << "post = s.posterior()\n"
      << "goals = [g[\"goal\"] for g in post[\"goals\"]]\n"
      << "steps = [[g[\"p\"] for g in st[\"posterior\"][\"goals\"]] for st in s.trace()]\n"
      << "d = s.assist()\n"
      << "print(json.dumps({\"goals\": goals, \"steps\": steps, \"action\": d[\"action\"], \"posterior\": post,\n"
      << "                  \"candidates\": [[c[\"action\"], c[\"value\"]] for c in d[\"candidates\"]]}))\n";
  }
  const json j = json::parse(stdout_of("PYTHONPATH=" + std::string(CLIPS_BINARY_DIR) + "/python /usr/bin/python3 " + script));
  FrontEndRun r;
  r.goals = j["goals"].get<std::vector<std::string>>();
  r.steps = j["steps"].get<std::vector<std::vector<double>>>();
  r.action = j["action"];
  r.posterior = j["posterior"];
  for (const auto& c : j["candidates"]) r.candidates.push_back({c[0], c[1]});
  return r;
}

void expect_same(const FrontEndRun& a, const FrontEndRun& b, const std::string& name) {
  EXPECT_EQ(a.goals, b.goals) << name;
  ASSERT_EQ(a.steps.size(), b.steps.size()) << name;
  for (size_t t = 0; t < a.steps.size(); ++t) expect_near_all(a.steps[t], b.steps[t], name + " step " + std::to_string(t));
  EXPECT_EQ(a.action, b.action) << name;
  expect_same_json(a.posterior, b.posterior, name + " posterior");
  ASSERT_EQ(a.candidates.size(), b.candidates.size()) << name;
  for (size_t i = 0; i < a.candidates.size(); ++i) {
    EXPECT_EQ(a.candidates[i].first, b.candidates[i].first) << name;
    EXPECT_NEAR(a.candidates[i].second, b.candidates[i].second, 1e-9) << name << " " << a.candidates[i].first;
  }
}

// ---- every repo dataset: the model trained on the domain's own corpus -------

// The goal posterior at each checkpoint t = 0..T of a plan: after t observed
// actions, with the utterances said then heard first at t = 0 and t = T and
// after the checkpoint otherwise (where `clips infer` scores them: in the
// step that follows).
using Checkpoints = std::vector<std::vector<double>>;

Checkpoints cli_checkpoints(const std::string& dir, const std::string& plan) {
  const json j = json::parse(stdout_of(std::string(CLIPS_BINARY_DIR) + "/clips infer --json --dataset " + dir +
                                       " --plan " + plan));
  Checkpoints out;
  for (const auto& st : j["steps"]) {
    std::vector<double> p;
    for (const auto& g : st["posterior"]["goals"]) p.push_back(g["p"]);
    out.push_back(std::move(p));
  }
  return out;
}

// Drives one front end through the plan: observe(action), hear(text), read().
template <class Observe, class Hear, class Read>
Checkpoints replay(const clips::data::PlanRecord& plan, Observe observe, Hear hear, Read read) {
  const int T = static_cast<int>(plan.observed.actions.size());
  Checkpoints out;
  for (int t = 0; t <= T; ++t) {
    if (t > 0) observe(plan.observed.actions[static_cast<size_t>(t - 1)].text);
    auto hear_all = [&] {
      for (const auto& u : plan.observed.utterances)
        if (u.index == t) hear(u.text);
    };
    if (t == 0 || t == T) hear_all();
    out.push_back(read());
    if (t != 0 && t != T) hear_all();
  }
  return out;
}

Checkpoints session_checkpoints(const std::string& dir, const clips::data::PlanRecord& plan) {
  auto s = clips::Session::open_dataset(dir, plan.id);
  return replay(
      plan, [&](const std::string& a) { s.observe(a); }, [&](const std::string& u) { s.hear(u); },
      [&] { return s.posterior().goal_probabilities; });
}

Checkpoints server_checkpoints(const std::string& dir, const clips::data::PlanRecord& plan) {
  // As `clips serve` sets it up (cmd_serve.cpp): the dataset's own model.
  clips::serve::Service service({dir}, {}, clips::language::make_language_model("embedded"));
  service.set_dataset_language_model([](const clips::data::Dataset& ds) {
    return clips::language::make_dataset_language_model("embedded", {}, ds);
  });
  auto call = [&](const std::string& method, const std::string& path, const json& body) {
    const auto reply = service.handle(method, path, body.is_null() ? "" : body.dump());
    EXPECT_LT(reply.status, 300) << path << ": " << reply.body;
    return json::parse(reply.body);
  };
  const std::string name = std::filesystem::path(dir).filename().string();
  const std::string id = call("POST", "/api/sessions", {{"dataset", name}, {"problem", plan.problem_id}, {"plan", plan.id}})["id"];
  return replay(
      plan, [&](const std::string& a) { call("POST", "/api/sessions/" + id + "/act", {{"action", a}}); },
      [&](const std::string& u) { call("POST", "/api/sessions/" + id + "/hear", {{"utterance", u}}); },
      [&] {
        const json j = call("GET", "/api/sessions/" + id + "/posterior", nullptr);
        std::vector<double> p;
        for (const auto& g : (j.contains("posterior") ? j["posterior"] : j)["goals"]) p.push_back(g["p"]);
        return p;
      });
}

// A Python session driven as above, and (in `run_plan`) clips_assist.run_plan's
// posteriors, which are `clips infer`'s steps.
Checkpoints python_checkpoints(const std::string& dir, const clips::data::PlanRecord& plan, Checkpoints* run_plan) {
  const std::string base = std::string(CLIPS_BINARY_DIR) + "/front_ends_repo_test";
  json events = {{"dir", dir}, {"plan", plan.id}, {"actions", json::array()}, {"said", json::array()}};
  for (const auto& a : plan.observed.actions) events["actions"].push_back(a.text);
  for (const auto& u : plan.observed.utterances) events["said"].push_back({u.index, u.text});
  std::ofstream(base + ".json") << events.dump();
  {
    std::ofstream f(base + ".py");
    f << "import json, sys, clips_assist\n"
      << "e = json.load(open(sys.argv[1]))\n"
      << "s = clips_assist.Session.open_dataset(e['dir'], e['plan'])\n"
      << "T = len(e['actions'])\n"
      << "def hear(t):\n"
      << "    for i, u in e['said']:\n"
      << "        if i == t: s.hear(u)\n"
      << "out = []\n"
      << "for t in range(T + 1):\n"
      << "    if t > 0: s.observe(e['actions'][t - 1])\n"
      << "    if t in (0, T): hear(t)\n"
      << "    out.append([g['p'] for g in s.posterior()['goals']])\n"
      << "    if t not in (0, T): hear(t)\n"
      << "whole = clips_assist.run_plan(e['dir'], e['plan'])\n"
      << "ran = [[g['p'] for g in st['posterior']['clips']['goals']] for st in whole['steps']]\n"
      << "print(json.dumps({'session': out, 'run_plan': ran}))\n";
  }
  const json j = json::parse(stdout_of("PYTHONPATH=" + std::string(CLIPS_BINARY_DIR) + "/python /usr/bin/python3 " +
                                       base + ".py " + base + ".json"));
  *run_plan = j["run_plan"].get<Checkpoints>();
  return j["session"].get<Checkpoints>();
}

}  // namespace front_ends_test
using namespace front_ends_test;
