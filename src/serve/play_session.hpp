#pragma once
// One interactive game on a problem of any pack: a person plays the human,
// the assistant infers their goal from what they do and say and acts by the
// chosen method. A thin driver over the session engine (src/engine), which
// owns the belief, the decisions and the trace; this file adds the server's
// own limits, the scene and the replies as plain JSON. The problem comes from
// a loaded dataset (with or without a recorded plan) or from PDDL text.
//
// Not thread-safe: the server serialises each session's requests.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "data/dataset.hpp"
#include "domains/dkg/dkg_world.hpp"
#include "domains/vh/vh_world.hpp"
#include "engine/engine.hpp"
#include "lm/language_model.hpp"
#include "serve/command_words.hpp"
#include "serve/text_scene.hpp"

namespace clips::serve {

// An action that does not apply in the current state (HTTP 409); the session
// is left as it was.
class ConflictError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Compute bounds of one session (each request's search work is bounded by these).
struct PlayLimits {
  size_t inference_nodes = size_t{1} << 18;  // per A* search while refining a belief
  size_t assist_nodes = size_t{1} << 16;     // per A* search of an assistance decision
  double search_seconds = 5;                 // per A* search
  int max_steps = 300;                       // actions per session (undo frees them)
  size_t max_utterance_bytes = 500;
  // Sessions from PDDL text: ground actions of one schema at most (the
  // grounder refuses more, naming the action). Interactive play searches
  // every state's successors: 45 things touched in triples by two agents
  // (182,250 actions, 91,125 successors a state) took 20 GB before a search
  // stopped.
  int64_t text_max_ground_actions = 50000;
  // ... and grounding such a problem takes at most this many seconds.
  double text_ground_seconds = 10;
  // Threads refining one session's belief. 1 (default): sessions already run
  // in parallel, one per request thread; 0: all cores, for a server that has
  // one player at a time (the hypotheses are refined in parallel; results do
  // not depend on it).
  int belief_threads = 1;
  // Every other belief option (particle inference and its settings; exact
  // enumeration by default). Its method, budgets and thread count are
  // replaced by the ones above.
  SessionOptions belief;
};

// The methods a player may switch between (names as in `clips assist`).
std::vector<std::string> play_methods();

// What a session plays (the engine's problem).
using PlaySetup = engine::Problem;

// A problem of a loaded dataset. `plan_id` picks the reference plan (cost
// profiles, true goal, the observed moves offered as hints); empty: the
// problem's first plan, or none when the problem has no plan (then the
// candidate goals follow the pack's goal rule and the profiles its default).
// `problem` must be one of ds->problem_ids() (never used as a path
// otherwise). Throws InputError naming the field ('problem', 'plan').
PlaySetup dataset_setup(std::shared_ptr<const data::Dataset> ds, std::string name, const std::string& problem,
                        const std::string& plan_id);
// A domain and problem as PDDL text, with the pack as JSON text ("": the one
// the domain's name finds, else the generic pack). A pack sent as text may
// not name files (fewshot.file, embedded_corpus). Throws InputError starting
// "field 'domain'", "field 'problem'" or "field 'pack'".
PlaySetup text_setup(const std::string& domain_pddl, const std::string& problem_pddl, const std::string& pack_json,
                     const PlayLimits& limits);

class PlaySession {
 public:
  // Throws InputError naming the field for an unknown method.
  PlaySession(PlaySetup setup, const std::string& method, std::shared_ptr<lm::LanguageModel> lm, PlayLimits limits);

  // Any agent's action as PDDL text, e.g. "(left human)". The assistant's own
  // actions are interventions (no evidence). InputError: not an action of the
  // problem; ConflictError: not applicable now.
  void act(const std::string& action);
  // An instruction heard in the current state.
  void hear(const std::string& utterance);
  // The assistant's next action by the session's method, with the expected
  // value of every candidate; `apply` also takes it. ConflictError when it is
  // not the assistant's turn.
  nlohmann::json assist(bool apply);
  // Takes back the last human action with everything after it (the
  // assistant's reply, instructions); ConflictError when there is none.
  void undo();
  void reset();
  void set_method(const std::string& method);

  // Every reply's session state (docs/api.md); the scene is data for any
  // pack: grid, cards, or text (places, holdings, facts, what changed).
  nlohmann::json state() const;
  nlohmann::json posterior() const;
  nlohmann::json trace() const;
  const std::string& method() const { return method_; }
  int steps() const { return engine_.t(); }
  // Whether the candidate goal with this label holds now (HTTP 400 for another label).
  bool goal_holds(const std::string& label) const { return engine_.goal_holds(label); }
  // The player's own goal, which the assistant is not told: a candidate
  // goal's label, or none (play freely). The game ends (reached_goal) when
  // it holds, not when another candidate goal does. Default: the reference
  // plan's true goal. InputError for a label that is not a candidate goal.
  void set_player_goal(const std::optional<std::string>& label);

 private:
  nlohmann::json scene() const;
  nlohmann::json decision() const;
  nlohmann::json reading() const;

  std::string dataset_name_, problem_;
  const data::PlanRecord* plan_ = nullptr;  // null: no reference plan
  int true_goal_ = -1;
  int player_goal_ = -1;  // -1: none
  std::vector<std::string> goal_conditions_;  // each candidate goal's PDDL condition, in goal order
  std::string principal_, assistant_;
  std::string method_;
  PlayLimits limits_;
  std::optional<domains::dkg::DkgWorld> dkg_;
  std::optional<domains::vh::VhWorld> vh_;
  std::optional<TextScene> text_;
  engine::Engine engine_;
  CommandWords words_;  // readings in parts, for the page to say in words
  // The assist results still in the history, oldest first, each with the
  // number of events the history had after it (an applied decision's action
  // is the last of them). The state shows the latest applied one whose
  // action is still in the history (undo takes it back with the action), or
  // a decision not applied while nothing has happened since.
  struct Decided {
    size_t events = 0;
    bool applied = false;
    nlohmann::json decision;
  };
  std::vector<Decided> decisions_;
};

}  // namespace clips::serve
