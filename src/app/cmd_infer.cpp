// `clips infer`: goal inference over one dataset plan (clips-spec.md 8).
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "data/dataset.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"

namespace clips::app {

void register_infer(CLI::App& app) {
  auto* cmd = app.add_subcommand("infer", "Infer the human's goal from a plan's actions and instruction (CLIPS)");
  struct Opts {
    std::string dataset, plan, modalities = "both";
    LmFlags lm;
    bool json = false;
    size_t max_nodes = size_t{1} << 18;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--dataset", o->dataset, "Dataset directory (with domain.pddl)")->required();
  cmd->add_option("--plan", o->plan, "Observed plan id, e.g. 2.1.keys")->required();
  cmd->add_option("--modalities", o->modalities,
                  "Which evidence the reported posterior uses: both (CLIPS, default), utterance or action")
      ->check(CLI::IsMember({"both", "utterance", "action"}));
  add_lm_options(cmd, o->lm);
  add_speaker_model_options(cmd, o->lm);
  cmd->add_option("--max-nodes", o->max_nodes, "Expansion budget per A* search in each refinement (default 2^18)");
  cmd->add_flag("--json", o->json, "Print {goals, true_goal, steps: [{t, posterior}]} as one JSON object");
  cmd->callback([o] {
    auto ds = data::Dataset::load(o->dataset);
    const auto& plan = ds.plan(o->plan);
    const inference::Modality modality = inference::parse_modality(o->modalities);
    auto lm = make_lm(o->lm);
    inference::InferenceOptions opts;
    opts.refine.max_nodes = o->max_nodes;
    opts.threads = 0;  // one plan: use every core
    opts.utterance.speaker_rule = inference::parse_speaker_rule(o->lm.speaker_rule);
    opts.utterance_timing = inference::parse_utterance_timing(o->lm.utterance_timing);
    const inference::InferenceRun run = inference::run_inference(ds, plan, *lm, opts);
    const std::string true_goal = run.true_goal >= 0 ? run.goals[run.true_goal] : "";
    if (o->json) {
      nlohmann::json j;
      j["plan"] = run.plan_id;
      j["modality"] = inference::to_string(modality);
      j["goals"] = run.goals;
      j["true_goal"] = true_goal;
      j["steps"] = nlohmann::json::array();
      for (const auto& st : run.steps) j["steps"].push_back({{"t", st.t}, {"posterior", st[modality].goals}});
      j["seconds"] = run.seconds;
      fmt::print("{}\n", j.dump());
      return;
    }
    fmt::print("plan {}: goal posterior ({}), true goal {}\n", run.plan_id, inference::to_string(modality), true_goal);
    fmt::print("{:>4}  {:<30}", "t", "action");
    std::vector<size_t> width;
    for (const auto& g : run.goals) width.push_back(std::max<size_t>(9, g.size()));
    for (size_t g = 0; g < run.goals.size(); ++g) fmt::print(" {:>{}}", run.goals[g], width[g]);
    fmt::print("\n");
    for (const auto& st : run.steps) {
      fmt::print("{:>4}  {:<30}", st.t, st.t == 0 ? "(start)" : st.action);
      for (size_t g = 0; g < width.size(); ++g) fmt::print(" {:>{}.4f}", st[modality].goals[g], width[g]);
      for (const auto& u : st.utterances) fmt::print("   <- \"{}\"", u.text);
      fmt::print("\n");
    }
    const auto& fin = run.steps.back()[modality];
    fmt::print("; cost profiles:");
    for (size_t c = 0; c < run.profiles.size(); ++c) fmt::print(" {} {:.4f}", run.profiles[c], fin.profiles[c]);
    fmt::print("; log marginal likelihood {:.4f}; {:.3f} s ({})\n", fin.log_marginal, run.seconds, lm->name());
  });
}

}  // namespace clips::app
