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
#include "clips/types.hpp"

namespace clips {

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

  // The same calls bounded by a wall-clock limit and a cancellation token
  // (clips::CallLimits): when either fires the call throws TimeLimitError or
  // CancelledError and the session is exactly as it was before the call.
  const Step& observe(const std::string& action, const CallLimits& limits);
  const Step& observe(int action_id, const CallLimits& limits);
  const Step& hear(const std::string& utterance, const CallLimits& limits);
  AssistDecision assist(const CallLimits& limits);
  // Takes back the human's latest move or instruction with everything after
  // it (the assistant's actions): an instruction heard after the last move
  // goes alone. False when there is none.
  bool undo(const CallLimits& limits = {});
  // Back to the initial state, with nothing observed.
  void reset();
  // Whether a candidate goal (its label, e.g. "gem2") holds in the current
  // state; InputError for a label that is not a candidate.
  bool goal_holds(const std::string& goal) const;

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
