#pragma once
// The assistant's decision policies in live sessions (Engine::decide), each
// registered once with its name, help and decide(): the session option
// `assistance`, Python's keyword, the server's field and its OpenAPI enum
// read that one table (engine::assistance_choices, engine/methods.hpp).
#include <functional>
#include <string>
#include <vector>

#include "assist/assist.hpp"
#include "clips/types.hpp"

namespace clips::engine {

// What one decision sees: the assistance set-up at the current state, the
// belief's hypotheses, the model time step, whether a round of waits just
// ended (assist::round_of_waits) and the states since the last instruction
// (what was asked and done since is not asked again).
struct DecisionInput {
  const assist::AssistSetup& setup;
  const std::vector<assist::Hypothesis>& hypotheses;
  const pddl::State& state;
  int t = 0;
  bool stalled = false;
  const std::vector<pddl::State>* since_instruction = nullptr;
};
using Decide = std::function<assist::Decision(const DecisionInput&)>;

struct DecisionPolicy {
  Assistance value;
  std::string name, help;
  Decide decide;
};

// Registers a policy: its name in the table, its decide() for the engine. A
// name or value registered twice is a bug (std::logic_error).
void register_assistance(DecisionPolicy policy);
// Takes a registered policy back out (a test's own registration).
void unregister_assistance(const std::string& name);
// The decide() of a registered policy; InputError for a value none has.
const Decide& decide_of(Assistance a);

}  // namespace clips::engine
