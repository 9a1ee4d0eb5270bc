#pragma once
// The vocabulary every clips front end shares (the session API, the server,
// the CLI, Python): methods, options, posteriors, decisions, trace steps and
// per-call limits. docs/architecture.md says what each noun means.
#include <atomic>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace clips {

// Which evidence the posterior uses, and how the assistant decides. One
// name table (src/engine/methods.cpp; docs/cli.md, "Named choices") serves
// CLI flags, Python keywords and JSON fields, and reads older spellings too.
enum class Method {
  Clips,         // actions and utterances
  LanguageOnly,  // utterances only (the actions still move the state)
  ActionOnly,    // actions only
  // The literal listener: the assistant does the most probable command of the
  // latest instruction (its posterior is the CLIPS one).
  Literal,
};
// The canonical name (method_names() lists them).
std::string method_name(Method m);
// Any known spelling; throws InputError listing the names.
Method parse_method(const std::string& text);
// The canonical names, in the table's order.
std::vector<std::string> method_names();

enum class Assistance {
  QMdp,   // Q_MDP: the action of highest posterior-weighted Q-value
  PiBar,  // pi-bar_MDP: the action the posterior mixture of policies takes most often
};
// One name table, as for methods (the decision policies' table, which
// registered policies join; Python keywords, the server's JSON fields).
std::string assistance_name(Assistance a);
// Throws InputError listing the names.
Assistance parse_assistance(const std::string& text);
std::vector<std::string> assistance_names();
// One line saying what the rule does, for help texts and the API's docs.
std::string assistance_help(Assistance a);

struct LanguageModelOptions {
  std::string backend = "embedded";  // "embedded" (offline) or "openai" (OpenAI-compatible completions server)
  std::string base_url;              // openai: default $CLIPS_LM_BASE_URL, else https://api.openai.com/v1
  std::string model;                 // openai: default $CLIPS_LM_MODEL, else davinci-002
  double timeout_seconds = 120;      // openai: per request
};

// Particle inference over goal x cost profile (sequential Monte Carlo; only
// the hypotheses particles hold are refined), tuned as docs/particles.md
// says. The one particle options type: the session's options, `clips infer`,
// `clips bench` and `clips serve` flags, Python keywords and the server's
// JSON all fill this struct, and one table (src/engine/options.hpp) names its
// fields (CLI flags are the names with '-' for '_'), parses and checks them.
struct ParticleOptions {
  int particles = 0;                       // particles per filter, 0 to 1,000,000; 0: exact enumeration
  uint64_t particle_seed = 1;              // results are a function of it
  double ess_threshold = 0.5;              // resample below this share of the particles, 0 to 1
  int rejuvenation_moves = 2;              // Metropolis-Hastings sweeps after each resampling, 0 to 100
  std::string rejuvenate = "evidence";     // when else they run: "evidence", "utterances" or "resampling"
  int proposal_groups = 8;                 // exploring proposals per sweep, 1 to 64
  std::string particle_filters = "all";    // "all" (one filter per modality) or "clips" (the CLIPS one only)
  std::string particle_estimate = "support";  // "support" (exact weights on the held hypotheses) or "weights"
  // Options registered at run time for a policy of one's own
  // (clips::register_option, include/clips/policy.hpp): name -> value as
  // text; an option not set here has its registered default. The same table
  // reads them from flags, keywords and JSON fields.
  std::map<std::string, std::string> registered_options;
};

// A session's options; the particle ones (unused when `particles` is 0) are
// inherited, so `options.particles = 64` reads as before.
struct SessionOptions : ParticleOptions {
  Method method = Method::Clips;
  Assistance assistance = Assistance::QMdp;
  LanguageModelOptions language_model;
  // Candidate goals as PDDL conditions, e.g. "(has human gem1)". Empty: the
  // domain pack's (docs/domains.md: Doors-Keys-Gems one per gem; VirtualHome
  // and the workshop the problem's goal set; without a pack the problem's :goal).
  std::vector<std::string> goals;
  // Candidate cost profiles: "unit", "task", or a profile the domain's pack
  // names ("1".."4" or "C1".."C4" in Doors-Keys-Gems). Empty: from the plan's
  // tag when a session is opened on a dataset plan; else the pack's default
  // rule (Doors-Keys-Gems {C3, C4}, the keys condition; without rules unit).
  std::vector<std::string> cost_profiles;
  size_t max_nodes = size_t{1} << 18;  // expansions per lookahead search
  // The assistant's decisions refine the hypotheses' policies at the current
  // state: expansions per search there (0: max_nodes).
  size_t assist_max_nodes = 0;
  // How Q_MDP breaks ties: "paper" or "request" ("": the domain pack's rule),
  // and which Q-values it floors at waiting to the horizon: "dead-ends" or
  // "horizon" (as `clips assist --assist-rule`, `--qa-floor`).
  std::string assist_rule;
  std::string qa_floor = "dead-ends";
  // Seconds per lookahead search, of inference and decisions (infinite:
  // none, the default; CallLimits bounds a whole call instead). A finite
  // value makes results depend on the machine's speed.
  double search_seconds = std::numeric_limits<double>::infinity();
  // Threads refining the hypotheses of one step. 0: all cores (results do
  // not depend on it); 1 when many sessions run at once (`clips serve` does).
  int threads = 0;
  // What is refined at the assistant's turns: "taken" (one lookahead, from
  // the state its action led to) or "all" (the paper's REFINE, every
  // successor); as `clips infer --assistant-turns`.
  std::string assistant_turns = "taken";
};

struct HypothesisWeight {
  std::string goal;          // label, e.g. "gem2"
  std::string cost_profile;  // name, e.g. "C3"
  double weight = 0;         // normalised posterior
};

struct Posterior {
  std::vector<std::string> goals;  // labels, in candidate order
  std::vector<double> goal_probabilities;
  std::vector<std::string> cost_profiles;
  std::vector<double> cost_profile_probabilities;
  std::vector<HypothesisWeight> hypotheses;  // every goal x cost profile
  double log_marginal_likelihood = 0;        // log P(observations); -inf when no hypothesis explains them
};

// Bounds of one call that may search (observe, hear, assist, undo). When the
// wall-clock limit passes or the call is cancelled, the call throws
// TimeLimitError or CancelledError and the session is left exactly as it was
// before the call. Cancellation is checked between refinements (and once the
// work is done: a flag raised during the call always cancels it); a single
// search stops at the time limit. The flag may be set from any thread (a
// controller's stop button); the call never writes it.
struct CallLimits {
  double seconds = std::numeric_limits<double>::infinity();  // wall clock of the whole call
  const std::atomic<bool>* cancel = nullptr;                 // cancelled when this flag becomes true
};

struct CandidateAction {
  int id = -1;
  std::string action;  // PDDL text, e.g. "(pickup robot key1)"
  double value = 0;    // Q_MDP: weighted Q-value (negative cost); pi-bar: probability
};

struct AssistDecision {
  // False when the human is to move: then `action` is empty and there are no candidates.
  bool assistant_turn = false;
  int id = -1;
  std::string action;  // the assistant's next action
  std::vector<CandidateAction> candidates;  // every action available to the assistant
  // Every likely hypothesis has the same best action; Q_MDP then takes it.
  bool unanimous = false;
  std::vector<std::string> goals;  // the goal weights the decision used (the session's method)
  std::vector<double> goal_weights;
  std::string method;  // the method that decided (method_name)
  std::string reason;  // why this action, in words
  // Literal: the most probable command of the latest instruction ("" when none).
  std::string command;
  double command_probability = 0;
  // Q_MDP's request rule broke a tie in favour of `request_command`, or
  // carried out `request_command`, what the instruction most probably asked
  // of the assistant (followed_request).
  bool broke_tie = false;
  bool followed_request = false;
  std::string request_command;
};

// One entry of the trace: the session's start (t = 0) or one observed action,
// with the utterances heard after it and the posterior then.
struct Step {
  int t = 0;
  std::string action;  // empty at t = 0
  std::string agent;   // who acted ("" at t = 0)
  bool evidence = false;  // a human action (the assistant's are interventions)
  std::vector<std::string> utterances;
  // For utterances heard here whose words the model mostly could not read
  // (weighted toward uniform, or ignored): why, one line each.
  std::vector<std::string> utterance_warnings;
  Posterior posterior;     // the session's method
  double seconds = 0;      // inference time of this step
};

}  // namespace clips
