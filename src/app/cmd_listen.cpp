// `clips listen`: the literal listener on a
// dataset plan: which command does an instruction ask for, in the state where
// it is spoken?
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "pddl/sexpr.hpp"
#include "app/cli.hpp"
#include "app/exit_codes.hpp"
#include "data/dataset.hpp"
#include "language/listener.hpp"
#include "lm/readability.hpp"
#include "util/error.hpp"
#include "util/utf8.hpp"

namespace clips::app {

namespace {

// The utterance the literal listener hears by default: mDKG has a literal
// (assistant-directed) rewrite per plan; VH plans (and mDKG plans without the
// file) carry their utterances in the observed plan, and the listener takes
// the last one.
std::string default_utterance(const std::string& dataset, const data::PlanRecord& p) {
  if (p.literal_utterance) {
    if (p.literal_utterance->find_first_not_of(" \t\r\n\f\v") == std::string::npos)
      throw InputError("the literal utterance file " + dataset + "/utterances/literal/" + p.id +
                       ".txt is empty; give --utterance");
    return *p.literal_utterance;
  }
  if (!p.observed.utterances.empty()) return p.observed.utterances.back().text;
  throw InputError("plan " + p.id + " has no utterance (no literal utterance file and none in the observed plan); "
                   "give --utterance");
}

}  // namespace

void register_listen(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "listen", "Literal listener: rank the commands an utterance may ask for, at the end of an observed plan");
  struct Opts {
    std::string dataset, plan;
    LmFlags lm;
    std::optional<std::string> utterance;
    int top = -1;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  add_dataset_option(cmd, o->dataset, "Dataset directory (with domain.pddl and problems/)");
  cmd->add_option("--plan", o->plan, "Plan id, e.g. 2.1.keys; the utterance is heard at the end of its observed part")
      ->required();
  cmd->add_option("--utterance", o->utterance,
                  "The instruction (default: the plan's literal utterance file, else the last utterance of the "
                  "observed plan)");
  add_lm_options(cmd, o->lm);
  cmd->add_option("--top", o->top, "Show only the N most probable commands (default: 10 in the table, all with --json)")
      ->check(PositiveInteger);
  cmd->add_flag("--json", o->json,
                "Print one JSON object {\"utterance\": ..., \"commands\": [{\"command\": ..., \"prob\": ...}, ...]}");
  cmd->callback([o] {
    // Reject a blank utterance before loading anything.
    if (o->utterance) {
      const auto& u = *o->utterance;
      if (u.find_first_not_of(" \t\r\n\f\v") == std::string::npos) throw UsageError("--utterance is empty");
      // Checked here, not by the JSON writer after the work.
      if (auto bad = util::utf8_problem(u); !bad.empty()) throw InputError("--utterance is " + bad);
    }
    auto ds = data::Dataset::load(dataset_dir(o->dataset));
    const auto& p = ds.plan(o->plan);
    auto task = ds.task(p.problem_id);
    const pddl::State s_T = pddl::simulate(*task, task->initial_state(), p.observed).states.back();
    const std::string utterance = o->utterance ? *o->utterance : default_utterance(o->dataset, p);

    const auto setup = language::literal_listener_setup(ds.pack_ptr());
    auto lm = make_lm(o->lm, ds);
    const auto result = language::literal_listener(*task, s_T, utterance, setup, *lm);

    // As infer warns: a ranking of words the model mostly cannot read is
    // close to the prior, and must not be taken for a reading.
    const double readable = lm::read_utterance(utterance).share();
    std::string warning;
    if (readable < 0.5)
      warning = fmt::format("the language model can read {:.0f}% of the utterance's words; this ranking says little "
                            "about what was asked",
                            100 * readable);
    if (!warning.empty()) fmt::print(stderr, "warning: {}\n", warning);

    const size_t n_all = result.commands.size();
    const size_t shown = o->top >= 0 ? std::min(n_all, static_cast<size_t>(o->top)) : (o->json ? n_all : std::min<size_t>(n_all, 10));
    if (o->json) {
      nlohmann::ordered_json j;  // keeps "utterance" before "commands"
      j["utterance"] = result.utterance;
      j["readable_share"] = readable;
      if (!warning.empty()) j["warning"] = warning;
      j["commands"] = nlohmann::ordered_json::array();
      for (size_t i = 0; i < shown; ++i)
        j["commands"].push_back({{"command", result.commands[i].command.display_form()}, {"prob", result.commands[i].prob}});
      fmt::print("{}\n", j.dump());
      return;
    }
    fmt::print("plan {} (problem {}), heard after {} observed actions\n", p.id, p.problem_id, p.observed.actions.size());
    fmt::print("utterance: \"{}\"\n", pddl::printable(result.utterance));
    fmt::print("{} candidate commands, language model {}\n", n_all, lm->name());
    // "done" = the plan's completion fulfils the command at some point: handy
    // when judging whether the listener understood the instruction.
    std::optional<pddl::State> achieved;
    if (!p.completed.actions.empty())
      achieved = language::achieved_facts(*task, pddl::simulate(*task, s_T, p.completed).states);
    fmt::print("{:>4}  {:>8}  {:>10}  {:>4}  {}\n", "rank", "prob", "log-lik", "done", "command");
    for (size_t i = 0; i < shown; ++i) {
      const auto& r = result.commands[i];
      std::string done = "-";
      if (achieved) done = language::state_satisfies_command(*task, *achieved, r.command, setup.config) ? "yes" : "no";
      fmt::print("{:>4}  {:>8.4f}  {:>10.3f}  {:>4}  {}\n", i + 1, r.prob, r.log_likelihood, done, r.command.display_form());
    }
    if (shown < n_all) fmt::print("({} more; use --top)\n", n_all - shown);
  });
}

}  // namespace clips::app
