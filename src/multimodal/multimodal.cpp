#include "multimodal/multimodal.hpp"

#include <fmt/core.h>

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "domains/dkg/dkg_world.hpp"
#include "domains/vh/vh_world.hpp"
#include "scenes/scenes.hpp"
#include "model/spec.hpp"
#include "render/image.hpp"
#include "util/error.hpp"

namespace clips::multimodal {

using pddl::ActionId;
using pddl::State;

bool MultimodalOptions::configured() const {
  if (!base_url.empty()) return true;
  const char* env = std::getenv("CLIPS_CHAT_BASE_URL");
  return env && *env;
}

namespace {

std::string shorten(const std::string& s, size_t n = 120) { return s.size() <= n ? s : s.substr(0, n) + "..."; }

// Models often wrap JSON in a ```json fence; accept exactly that, nothing looser.
std::string strip_fence(const std::string& text) {
  auto b = text.find_first_not_of(" \t\r\n");
  auto e = text.find_last_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  std::string t = text.substr(b, e - b + 1);
  if (t.rfind("```", 0) == 0 && t.size() >= 6 && t.compare(t.size() - 3, 3, "```") == 0) {
    auto nl = t.find('\n');
    if (nl == std::string::npos) return t;
    t = t.substr(nl + 1, t.size() - 3 - (nl + 1));
  }
  return t;
}

// PNG file bytes of an image (through a private temporary file).
std::vector<std::uint8_t> png_bytes(const render::Image& img) {
  static std::atomic<unsigned> counter{0};
  auto path = std::filesystem::temp_directory_path() /
              fmt::format("clips-multimodal-{}-{}.png", static_cast<long>(getpid()), counter++);
  render::write_png(img, path);
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::error_code ec;
  std::filesystem::remove(path, ec);
  if (bytes.empty()) throw std::runtime_error("cannot encode the state picture as PNG");
  return bytes;
}

}  // namespace

MultimodalAnswer parse_multimodal_answer(const std::string& text, const std::vector<std::string>& goals) {
  nlohmann::json j = nlohmann::json::parse(strip_fence(text), nullptr, false);
  if (j.is_discarded()) throw MultimodalError("the answer is not valid JSON: " + shorten(text));
  if (!j.is_object()) throw MultimodalError("the answer is JSON but not an object: " + shorten(text));
  MultimodalAnswer a;
  if (!j.contains("goal_probabilities")) throw MultimodalError("the answer has no \"goal_probabilities\" field");
  const auto& gp = j["goal_probabilities"];
  if (!gp.is_object())
    throw MultimodalError("\"goal_probabilities\" must be an object mapping goal names to numbers, got " +
                          shorten(gp.dump()));
  a.goal_posterior.assign(goals.size(), 0.0);
  std::vector<bool> seen(goals.size(), false);
  for (auto it = gp.begin(); it != gp.end(); ++it) {
    size_t g = std::find(goals.begin(), goals.end(), it.key()) - goals.begin();
    if (g == goals.size()) {
      std::string known;
      for (auto& k : goals) known += (known.empty() ? "" : ", ") + k;
      throw MultimodalError("\"goal_probabilities\" names an unknown goal \"" + it.key() + "\" (candidates: " + known + ")");
    }
    if (!it.value().is_number())
      throw MultimodalError("\"goal_probabilities\"." + it.key() + " must be a number, got " + it.value().dump());
    double p = it.value().get<double>();
    if (!std::isfinite(p) || p < 0 || p > 1)
      throw MultimodalError("\"goal_probabilities\"." + it.key() + " must be in [0, 1], got " + it.value().dump());
    a.goal_posterior[g] = p;
    seen[g] = true;
  }
  double sum = 0;
  for (double p : a.goal_posterior) sum += p;
  if (sum <= 0) throw MultimodalError("\"goal_probabilities\" sum to 0");
  for (size_t g = 0; g < goals.size(); ++g)
    if (!seen[g]) a.notes.push_back("goal " + goals[g] + " missing from goal_probabilities; taken as 0");
  if (std::abs(sum - 1) > 1e-6) {
    a.notes.push_back(fmt::format("goal_probabilities sum to {:.4g}; renormalised", sum));
    for (double& p : a.goal_posterior) p /= sum;
  }
  if (!j.contains("actions")) throw MultimodalError("the answer has no \"actions\" field");
  const auto& acts = j["actions"];
  if (!acts.is_array()) throw MultimodalError("\"actions\" must be an array of strings, got " + shorten(acts.dump()));
  for (size_t i = 0; i < acts.size(); ++i) {
    if (!acts[i].is_string())
      throw MultimodalError(fmt::format("\"actions\"[{}] must be a string, got {}", i, shorten(acts[i].dump())));
    a.actions.push_back(acts[i].get<std::string>());
  }
  return a;
}

std::string multimodal_rules(const domains::Pack& pack) {
  if (!pack.spec().rules_text.empty()) return pack.spec().rules_text;
  const domains::Roles& r = pack.roles();
  return "Rules of the " + pack.name() + " world (its PDDL actions are the moves). Two agents take turns: the " +
         r.principal + " (the human) and the " + r.assistant + " (you, the assistant). The " + r.principal +
         " wants one of the candidate goals; the " + r.assistant + " should help reach it.";
}

lm::ChatRequest multimodal_request(const data::Dataset& ds, const data::PlanRecord& plan, const State& s_T,
                                   const std::vector<std::string>& goals, int cell_px) {
  auto task = ds.task(plan.problem_id);
  std::string utterance;
  for (const auto& u : plan.observed.utterances) utterance += (utterance.empty() ? "" : " ") + u.text;
  render::RenderOptions ro;
  ro.cell_px = cell_px;
  ro.labels = render::RenderOptions::Labels::Always;
  render::Image img;
  const domains::Pack& pack = ds.pack();
  const std::string assistant = pack.roles().assistant;
  const std::string objects = pack.object_list(*task);
  switch (pack.spec().scene) {
    case domains::SceneKind::Cards: img = render::render_png(scenes::vh_scene(pack, domains::vh::VhWorld(*task), s_T, {utterance, "", {}, {}}), ro); break;
    case domains::SceneKind::Grid: img = render::render_png(scenes::dkg_scene(domains::dkg::DkgWorld(*task), s_T, {utterance, "", {}, {}}), ro); break;
    case domains::SceneKind::Text:
      throw InputError("the multimodal baseline needs a picture, and the " + pack.name() + " pack draws none (scene \"text\")");
  }
  std::string goal_list;
  for (auto& g : goals) goal_list += (goal_list.empty() ? "" : ", ") + g;

  std::string prompt = multimodal_rules(pack) + "\n\n" +
                       "The picture shows the current state. Objects: " + objects + ".\n" +
                       "The human just said: \"" + utterance + "\"\n" + "Candidate goals: " + goal_list + ".\n\n" +
                       "Answer with one JSON object and nothing else, of the form\n"
                       "{\"goal_probabilities\": {\"" + goals.front() + "\": 0.5, ...}, \"actions\": [\"(action " +
                       assistant + " ...)\", ...]}\n"
                       "goal_probabilities gives a probability for every candidate goal (summing to 1); actions "
                       "lists the next actions of the " + assistant + ", in PDDL form, for its own turns only.";
  lm::ChatRequest req;
  lm::ChatMessage sys{"system", {lm::ChatPart::from_text("You are a helpful assistant that answers in strict JSON.")}};
  lm::ChatMessage user{"user", {lm::ChatPart::from_text(prompt), lm::ChatPart::from_png(png_bytes(img))}};
  req.messages = {sys, user};
  req.temperature = 0.0;
  req.json_object = true;
  req.validate_json = false;  // parse_multimodal_answer reports it, naming the problem
  return req;
}

assist::AssistResult execute_assistant_actions(const assist::AssistSetup& setup, const std::vector<std::string>& actions,
                                               search::Policy truth, std::vector<std::string>& notes) {
  const pddl::Task& task = *setup.task;
  const ActionId wait = setup.turns().noop(task, setup.assistant);
  const auto assistant = task.find_object(setup.assistant);
  auto play = [&](const State& s, size_t i) {
    const std::string& text = actions[i];
    const auto found = task.find_action(text);
    if (!found) {
      notes.push_back("action \"" + text + "\" is not a ground action of this problem; the " + setup.assistant +
                      " waits");
    } else if (task.action(*found).args.empty() || !assistant || task.action(*found).args[0] != *assistant) {
      notes.push_back("action " + text + " is not the " + setup.assistant + "'s; the " + setup.assistant + " waits");
    } else if (!task.applicable(*found, s.data())) {
      const auto& ga = task.action(*found);
      notes.push_back("action " + text + " is illegal here (" + task.explain_inapplicable(ga.schema, ga.args, s) +
                      "); the " + setup.assistant + " waits");
    } else {
      return *found;
    }
    return wait;
  };
  return assist::scripted_episode(setup, std::move(truth), actions.size(), play);
}

MultimodalRun run_multimodal(const data::Dataset& ds, const data::PlanRecord& plan, const assist::AssistSetup& setup,
                             const std::vector<std::string>& goals, const search::Policy& truth,
                             const MultimodalOptions& options) {
  if (goals.empty()) throw InputError("plan " + plan.id + ": no candidate goals");
  lm::OpenAiChatOptions co;
  co.base_url = options.base_url;
  co.model = options.model;
  co.api_key = options.api_key;
  co.http = options.http;
  lm::OpenAiChatClient client(co);
  auto req = multimodal_request(ds, plan, setup.start, goals, options.cell_px);
  req.max_tokens = options.max_tokens;
  MultimodalRun run;
  run.raw_answer = client.complete(req);
  try {
    run.answer = parse_multimodal_answer(run.raw_answer, goals);
  } catch (const MultimodalError& e) {
    throw MultimodalError(std::string("multimodal answer from ") + client.endpoint() + ": " + e.what());
  }
  run.notes = run.answer.notes;
  run.result = execute_assistant_actions(setup, run.answer.actions, truth, run.notes);
  return run;
}

}  // namespace clips::multimodal
