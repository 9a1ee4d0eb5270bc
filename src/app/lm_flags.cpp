// Shared --lm flags of the subcommands.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/choice_option.hpp"
#include "app/cli.hpp"
#include "assist/assist.hpp"
#include "domains/pack.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"
#include "util/error.hpp"
#include "util/program_name.hpp"

namespace clips::app {

void add_lm_options(CLI::App* cmd, LmFlags& f) {
  add_choice_option(cmd, "--lm", f.kind, language::language_model_choices(), "Language model (default embedded)");
  cmd->add_option("--lm-base-url", f.base_url,
                  "openai: completions API base URL, http:// or https:// (default $CLIPS_LM_BASE_URL, else "
                  "$OPENAI_BASE_URL, else https://api.openai.com/v1; the key is read from $OPENAI_API_KEY). At "
                  "start-up one short text is scored, and one line on stderr says whether and how the server "
                  "can score (vLLM and servers that echo the prompt with logprobs can; llama.cpp and Ollama cannot)")
      ->check(HttpUrl);
  cmd->add_option("--lm-model", f.model, "openai: model name (default $CLIPS_LM_MODEL, else davinci-002)");
  cmd->add_option("--lm-timeout", f.lm_timeout,
                  "openai (and the multimodal method's chat server): seconds one request may take before it counts "
                  "as timed out (default 120; rounded up to whole milliseconds); a "
                  "timed-out request is tried once more, connection failures and HTTP 429/5xx up to 4 more times (not a 5xx "
                  "that says a feature is not supported: that answer is final)")
      ->check(PositiveSeconds);
  cmd->add_option("--lm-max-reply-mb", f.lm_max_reply_mb,
                  "openai: largest reply accepted, in MiB (default 16); a longer reply is an error, so a server "
                  "that streams without end cannot fill memory")
      ->check(CLI::Range(0.001, 4096.0));
  cmd->add_option("--lm-batch-size", f.lm_batch_size, "openai: prompts per request (default 16; 1 to 1024)")
      ->check(PositiveInteger)
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--lm-single-prompt", f.lm_single_prompt,
                "openai: send each prompt alone, as a string rather than an array (servers that refuse an array, "
                "such as Ollama's; the start-up check switches to it by itself)");
  cmd->add_flag("--lm-prompt-logprobs", f.lm_prompt_logprobs,
                "openai: ask for vLLM's prompt_logprobs instead of echo + logprobs (as $CLIPS_LM_PROMPT_LOGPROBS=1; "
                "the start-up check tries it by itself when the server refuses or ignores echo)");
}

void add_speaker_model_options(CLI::App* cmd, LmFlags& f) {
  add_choice_option(cmd, "--utterance-timing", f.utterance_timing, inference::utterance_timing_choices(),
                    "State that explains an utterance given after k actions (default after)");
  add_choice_option(cmd, "--speaker-rule", f.speaker_rule, inference::speaker_rule_choices(),
                    "Which of the human's own actions the CLIPS speaker model's commands keep (default paper)");
  add_choice_option(cmd, "--assistant-turns", f.assistant_turns, inference::assistant_turns_choices(),
                    "Refinement at the assistant's turns, where no action is scored (default taken; the same "
                    "posteriors unless a search hits its node budget; taken searches less)");
  add_choice_option(cmd, "--speaker-plans", f.speaker_plans, domains::speaker_plans_choices(),
                    "Which joint plans the speaker model may have in mind (default: the pack's "
                    "inference.rollout.plans)");
  cmd->add_option("--utterance-noise", f.utterance_noise,
                  "Weight in [0, 1) of the utterance model's noise: each goal's utterance likelihood is mixed with "
                  "the mean over the goals, so one misread word cannot rule a goal out (0: the bare model); "
                  "default: the pack's inference.utterance_noise")
      ->check(CLI::Range(0.0, 0.999999));
  cmd->add_option("--utterance-exponent", f.utterance_exponent,
                  "Exponent in (0, 10] the robust utterance likelihood is raised to: how many independent "
                  "observations the words count as (1: the bare model); default: the pack's "
                  "inference.utterance_exponent")
      ->check(CLI::Range(1e-6, 10.0));
}

void add_assistance_options(CLI::App* cmd, LmFlags& f) {
  add_choice_option(cmd, "--qa-floor", f.qa_floor, assist::qa_floor_choices(),
                    "Which Q-values Q_MDP floors at the cost of waiting to the horizon (default dead-ends)");
  add_choice_option(cmd, "--assist-rule", f.assist_rule, assist::assist_rule_choices(),
                    "How Q_MDP picks among actions of equal expected value (default: the pack's assistance_rule)");
}

namespace {
std::optional<domains::RolloutSettings::Plans> parse_plans(const std::string& text) {
  if (text.empty()) return std::nullopt;
  return domains::speaker_plans_choices().parse(text);
}
}  // namespace

void apply_model_flags(const LmFlags& f, inference::InferenceOptions& io) {
  io.utterance.speaker_rule = inference::parse_speaker_rule(f.speaker_rule);
  io.utterance.plans = parse_plans(f.speaker_plans);
  io.utterance_timing = inference::parse_utterance_timing(f.utterance_timing);
  io.assistant_turns = inference::parse_assistant_turns(f.assistant_turns);
  if (f.utterance_noise >= 0) io.utterance_noise = f.utterance_noise;
  if (f.utterance_exponent > 0) io.utterance_exponent = f.utterance_exponent;
}

void apply_model_flags(const LmFlags& f, eval::ExperimentOptions& eo) {
  eo.speaker_rule = inference::parse_speaker_rule(f.speaker_rule);
  eo.speaker_plans = parse_plans(f.speaker_plans);
  eo.utterance_timing = inference::parse_utterance_timing(f.utterance_timing);
  eo.assistant_turns = inference::parse_assistant_turns(f.assistant_turns);
  eo.qa_floor = assist::parse_qa_floor(f.qa_floor);
  if (!f.assist_rule.empty()) eo.assist_rule = assist::parse_assist_rule(f.assist_rule);
  if (f.utterance_noise >= 0) eo.utterance_noise = f.utterance_noise;
  if (f.utterance_exponent > 0) eo.utterance_exponent = f.utterance_exponent;
}

language::LanguageModelOptions lm_options(const LmFlags& f) {
  if (f.checked) return *f.checked;
  language::LanguageModelOptions o;
  o.base_url = f.base_url;
  o.model = f.model;
  o.timeout_seconds = f.lm_timeout;
  o.max_reply_mb = f.lm_max_reply_mb;
  o.batch_size = f.lm_batch_size;
  o.single_prompt = f.lm_single_prompt;
  if (f.lm_prompt_logprobs) o.prompt_logprobs = true;
  return o;
}

void check_lm_server(LmFlags& f) {
  if (f.kind != "openai" || f.checked) return;
  const language::ServerCheck check = language::check_language_model_server(lm_options(f));
  std::fprintf(stderr, "%s: %s\n", util::program_name().c_str(), check.line.c_str());
  f.checked = check.options;
}

void require_stimuli(const data::Dataset& ds) {
  if (!ds.stimuli_error().empty())
    throw InputError(ds.stimuli_error() + " (fix the file, or remove it: it is optional)");
}

std::chrono::milliseconds lm_timeout_ms(const LmFlags& f) {
  return std::chrono::milliseconds(std::max(1LL, static_cast<long long>(std::ceil(std::min(f.lm_timeout, 1e9) * 1000))));
}

std::shared_ptr<lm::LanguageModel> make_lm(LmFlags& f) {
  check_lm_server(f);
  return language::make_language_model(f.kind, lm_options(f));
}

std::shared_ptr<lm::LanguageModel> make_lm(LmFlags& f, const data::Dataset& ds) {
  check_lm_server(f);
  return language::make_dataset_language_model(f.kind, lm_options(f), ds);
}

}  // namespace clips::app
