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

// What a decision sees and the policy's signature are the simulated
// episodes' too (assist/assist.hpp): the bench calls the same decide().
using DecisionInput = assist::DecisionInput;
using Decide = assist::Decide;

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
// The bench's names of Q_MDP's two episode kinds ("qmdp_offline",
// "qmdp_online"; eval::assist_policy_choices): no policy may take them.
std::vector<std::string> reserved_policy_names();

}  // namespace clips::engine
