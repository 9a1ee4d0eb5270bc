#pragma once
// The `clips` command line: one register_* function per subcommand. Each
// subcommand is a thin layer over the library API of the same name.
#include <chrono>
#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>

#include "clips/errors.hpp"
#include "clips/types.hpp"
#include "data/dataset.hpp"
#include "eval/experiment.hpp"
#include "language/listener.hpp"
#include "lm/language_model.hpp"

namespace clips::app {

// Exit status of the subcommand that ran (0 = success).
extern int g_exit_code;

// The dataset directory default: $CLIPS_DATASET, else ../shared/dataset/<domain>.
std::string default_dataset_hint();

// --dataset DIR. Optional on the command line: without it, $CLIPS_DATASET is
// used when it names a dataset (a folder with domain.pddl). With it, a DIR
// that does not exist is looked up under $CLIPS_DATASET, so that with
// CLIPS_DATASET=../shared/dataset, `--dataset doors-keys-gems` works.
void add_dataset_option(CLI::App* cmd, std::string& dir, const std::string& help);
// The directory to load; throws UsageError when there is none.
std::string dataset_dir(const std::string& given);

// Checks for numeric options, failing at parse time with a plain message
// (CLI::PositiveNumber lets "nan" through and names its bound as 1.79769e+308).
extern const CLI::Validator PositiveInteger;     // 1, 2, ...
extern const CLI::Validator NonNegativeInteger;  // 0, 1, ...
extern const CLI::Validator HttpUrl;             // http://... or https://...
extern const CLI::Validator PositiveSeconds;     // a finite number > 0
extern const CLI::Validator SeedValue;           // 0 .. 2^64-1 (CLI11 would wrap -1 and 2^64 silently)
extern const CLI::Validator NodeBudget;          // a search's expansion budget: 1 .. 2^30
extern const CLI::Validator FiniteNumber;        // not NaN or an infinity (a Range lets NaN through)
// Adds FiniteNumber to every floating-point option of `app` and its
// subcommands, so that no number anywhere can be NaN or infinite.
void require_finite_numbers(CLI::App& app);

// --time-limit SECONDS of infer and assist: a wall-clock limit on `what`
// (the session engine's CallLimits); reaching it exits with kExitLimit.
void add_time_limit_option(CLI::App* cmd, std::optional<double>& seconds, const std::string& what);
std::string time_limit_message(const std::string& command, double seconds);
// With --time-limit: problems the dataset grounds from now on stop at it too
// (grounding a large problem can take longer than the inference after it).
void bound_grounding(data::Dataset& ds, const std::string& command, const std::optional<double>& seconds);
// Runs `f` with the limit; a TimeLimitError becomes one naming the command and
// the limit ("infer: stopped: --time-limit of 2 s reached ...").
template <typename F>
auto with_time_limit(const std::string& command, const std::optional<double>& seconds, F&& f) {
  CallLimits limits;
  if (seconds) limits.seconds = *seconds;
  try {
    return f(limits);
  } catch (const TimeLimitError& e) {
    throw TimeLimitError(time_limit_message(command, *seconds));
  }
}

// The language-model flags every subcommand that scores utterances shares:
// --lm embedded|openai, --lm-base-url, --lm-model (key from $OPENAI_API_KEY).
struct LmFlags {
  std::string kind = "embedded";
  std::string base_url, model;
  double lm_timeout = 120;  // seconds per HTTP attempt (openai)
  double lm_max_reply_mb = 16;  // largest reply accepted (openai)
  std::size_t lm_batch_size = 16;   // prompts per request (openai)
  bool lm_single_prompt = false;    // one prompt per request, as a string (openai; Ollama)
  bool lm_prompt_logprobs = false;  // vLLM's prompt_logprobs instead of echo (openai)
  // What the start-up check learnt of the server (check_lm_server); set once.
  std::optional<language::LanguageModelOptions> checked;
  std::string speaker_rule = "paper";  // CLIPS speaker commands: paper or code (the reference's)
  std::string utterance_timing = "after";  // state explaining an utterance: after (s_k) or before (s_{k-1})
  std::string assistant_turns = "taken";  // refinement at the assistant's turns (inference::AssistantTurns)
  std::string qa_floor = "dead-ends";      // Q_MDP floor: dead-ends or horizon (assist::QaFloor)
  std::string speaker_plans;  // "" (the pack's) or a name of domains::speaker_plans_choices()
  std::string assist_rule;    // "" (the pack's), paper or request (assist::AssistRule)
  double utterance_noise = -1;     // < 0: the pack's inference.utterance_noise
  double utterance_exponent = -1;  // <= 0: the pack's inference.utterance_exponent
};
void add_lm_options(CLI::App* cmd, LmFlags& flags);
// --speaker-rule and --utterance-timing, for the subcommands that run CLIPS inference.
void add_speaker_model_options(CLI::App* cmd, LmFlags& flags);
// --qa-floor, for the subcommands that run Q_MDP assistance.
void add_assistance_options(CLI::App* cmd, LmFlags& flags);
// What the speaker-model and assistance flags say, into an experiment's or an
// inference's options (the same parsing for every subcommand).
void apply_model_flags(const LmFlags& flags, eval::ExperimentOptions& options);
void apply_model_flags(const LmFlags& flags, inference::InferenceOptions& options);
// The options the --lm flags say, for every subcommand alike (after
// check_lm_server, adapted to what the server takes).
language::LanguageModelOptions lm_options(const LmFlags& flags);
// --lm openai: asks the server once to score a short text, prints the
// one-line outcome on stderr and keeps what it learnt in `flags`; throws
// LmError (exit 6) with that line when the server cannot score a given text.
// Nothing for the embedded model, or when already checked.
void check_lm_server(LmFlags& flags);
// --lm-timeout in milliseconds, rounded up (never 0, which libcurl reads as
// "no timeout"); it also bounds each request of the multimodal chat method.
std::chrono::milliseconds lm_timeout_ms(const LmFlags& flags);

// A dataset whose stimuli.json is present but does not read is an input
// error for infer, assist and bench too (validate reports it per plan).
void require_stimuli(const data::Dataset& ds);
// Both run check_lm_server first.
std::shared_ptr<lm::LanguageModel> make_lm(LmFlags& flags);
// The model for a dataset's domain (language::make_dataset_language_model).
std::shared_ptr<lm::LanguageModel> make_lm(LmFlags& flags, const data::Dataset& ds);

void register_validate(CLI::App& app);
void register_show(CLI::App& app);
void register_plan(CLI::App& app);
void register_bench(CLI::App& app);
void register_assist(CLI::App& app);
void register_infer(CLI::App& app);
void register_listen(CLI::App& app);
void register_lm_score(CLI::App& app);
void register_export_strips(CLI::App& app);
void register_render(CLI::App& app);
void register_serve(CLI::App& app);
void register_generate(CLI::App& app);

}  // namespace clips::app
