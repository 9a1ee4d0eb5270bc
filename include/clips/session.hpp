#pragma once
// clips::Session: live goal inference and assistance. Feed it what the human
// (or the assistant) just did and said; ask what it believes and what the
// assistant should do next.
//
//   auto s = clips::Session::open_dataset("data/examples/doors-keys-gems", "e1");
//   s.observe("(left human)");
//   s.observe("(wait robot)");
//   s.hear("Can you get me the yellow key?");
//   clips::Posterior p = s.posterior();   // goals, cost profiles, hypotheses
//   clips::AssistDecision d = s.assist(); // the robot's next action and why
//
// Model. The human has one of the candidate goals and cost profiles (uniform
// prior); their actions are Boltzmann-rational under the joint plans each
// hypothesis implies, and an utterance is scored by the language model under
// the commands those plans would give the assistant (CLIPS, the AAMAS 2024
// paper). The assistant's own actions are interventions: they change the
// state but carry no evidence about the goal. An utterance is explained from
// the state it is heard in.
//
// Errors are exceptions from clips/errors.hpp naming the offending input. A
// failed observe() or hear() leaves the session as it was.
//
// Thread safety. Distinct sessions may be used at the same time from distinct
// threads (they share nothing mutable; the embedded language model is loaded
// once per process under a lock). One session is not re-entrant: calls on the
// same session, const ones included, must not overlap.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "clips/errors.hpp"

namespace clips {

// Which evidence the posterior (and so the assistance) uses.
enum class Method {
  Clips,         // actions and utterances
  LanguageOnly,  // utterances only (the actions still move the state)
  ActionOnly,    // actions only
};

enum class Assistance {
  QMdp,   // Q_MDP: the action of highest posterior-weighted Q-value
  PiBar,  // pi-bar_MDP: the action the posterior mixture of policies takes most often
};

struct LanguageModelOptions {
  std::string backend = "embedded";  // "embedded" (offline) or "openai" (OpenAI-compatible completions server)
  std::string base_url;              // openai: default $CLIPS_LM_BASE_URL, else https://api.openai.com/v1
  std::string model;                 // openai: default $CLIPS_LM_MODEL, else davinci-002
  double timeout_seconds = 120;      // openai: per request
};

struct SessionOptions {
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
  // Threads refining the hypotheses of one step. 0: all cores (results do
  // not depend on it); 1 when many sessions run at once (`clips serve` does).
  int threads = 0;
  // Particle inference over goal x cost profile (sequential Monte Carlo with
  // this many particles; only the hypotheses particles hold are refined).
  // 0: exact enumeration. Results are a function of particle_seed.
  int particles = 0;
  uint64_t particle_seed = 1;
  // Particle tuning, as `clips infer`'s options of the same names
  // (README.md, "Particle inference"); unused when particles is 0.
  double ess_threshold = 0.5;              // resample below this share of the particles, in [0, 1]
  int rejuvenation_moves = 2;              // Metropolis-Hastings sweeps after each resampling, >= 0
  std::string rejuvenate = "evidence";     // when else they run: "evidence", "utterances" or "resampling"
  int proposal_groups = 8;                 // exploring proposals per sweep, >= 1
  std::string particle_filters = "all";    // "all" (one filter per modality) or "clips" (the CLIPS one only)
  std::string particle_estimate = "support";  // "support" (exact weights on the held hypotheses) or "weights"
  // What is refined at the assistant's turns: "taken" (one lookahead, from
  // the state its action led to) or "all" (the spec's REFINE, every
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
};

// One entry of the trace: the session's start (t = 0) or one observed action,
// with the utterances heard after it and the posterior then.
struct Step {
  int t = 0;
  std::string action;  // empty at t = 0
  std::string agent;   // who acted ("" at t = 0)
  bool evidence = false;  // a human action (the assistant's are interventions)
  std::vector<std::string> utterances;
  Posterior posterior;     // the session's method
  double seconds = 0;      // inference time of this step
};

class Session {
 public:
  // A problem of a dataset directory (the paper's layout: domain.pddl,
  // problems/<id>.pddl, ...; plans/ may be absent). `problem` is a problem id
  // ("2") or a plan id ("2.1.keys"); a plan id takes the plan's candidate
  // goals and cost profiles, but the session starts from the problem's
  // initial state (the plan's actions are not observed).
  static Session open_dataset(const std::string& dataset_dir, const std::string& problem, SessionOptions options = {});
  // A domain folder (holding domain.pddl; any domain with a language pack)
  // and a problem file.
  static Session open_domain(const std::string& domain_dir, const std::string& problem_file,
                             SessionOptions options = {});
  // A domain and a problem given as PDDL text rather than files, with the
  // domain's pack as JSON text (docs/domains.md; "": the pack the domain's
  // name finds, as for a folder without pack.json: data/domains/<name>/,
  // a compiled-in pack, else the generic one). The candidate goals follow
  // the pack's rule for the problem (objects of a type, or the problem's
  // :goal); a pack that reads goal sets needs SessionOptions::goals. Errors
  // name "<domain text>", "<problem text>" or "<pack text>" with the line and
  // column. A pack given as text has no folder: a relative fewshot.file is
  // read from the working directory.
  static Session open_domain_text(const std::string& domain_pddl, const std::string& problem_pddl,
                                  const std::string& pack_json = "", SessionOptions options = {});

  Session(Session&&) noexcept;
  Session& operator=(Session&&) noexcept;
  ~Session();

  // An action of either agent in the current state, as PDDL text or as an id
  // (see applicable_actions()). Throws InputError for text that names no
  // action, InapplicableActionError when its precondition is false.
  const Step& observe(const std::string& action);
  const Step& observe(int action_id);
  // An utterance heard in the current state. Throws InputError for empty or
  // non-UTF-8 text, LanguageModelError when the model fails.
  const Step& hear(const std::string& utterance);

  Posterior posterior() const;               // the session's method
  Posterior posterior(Method method) const;  // any method (one inference serves all three)
  // The assistant's next action in the current state under the session's
  // assistance rule. Refines the hypotheses' plans at the current state (as
  // the next observe() would); the posterior is not changed.
  AssistDecision assist();

  int t() const;                          // actions observed so far
  std::string state() const;              // printable (an ASCII map for Doors-Keys-Gems)
  const std::vector<Step>& trace() const;  // trace()[t]: after t actions
  std::string domain() const;             // the PDDL domain's name (its pack's), e.g. "doors-keys-gems"
  std::string active_agent() const;       // who is to move
  bool assistant_turn() const;
  // The actions applicable now (id, PDDL text), the active agent's.
  std::vector<CandidateAction> applicable_actions() const;
  std::string action_name(int action_id) const;  // throws InputError for an unknown id

 private:
  struct Impl;
  friend struct SessionInternals;  // in-tree front ends that draw the state
  explicit Session(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// The library's version ("0.1.0").
std::string library_version();
// Where the library reads its data (language corpora, domain packs):
// $CLIPS_DATA_DIR, else <prefix>/share/clips-assist of the installed library
// (for the installed static library: its configured datadir, then
// /usr/local/share/clips-assist and /usr/share/clips-assist), else, for a
// build-tree binary, the source tree it was built from.
std::string data_directory();

}  // namespace clips
