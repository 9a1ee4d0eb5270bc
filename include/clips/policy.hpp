#pragma once
// A decision policy of your own: how the assistant picks its next action.
// Registered once, it sits in the same table as the built-in policies: a
// Session decides by it (SessionOptions::assistance), `clips serve` and
// Python take its name, and the bench runs its episodes ("clips/NAME").
//
//   clips::register_policy("idle", "never helps", [](const clips::PolicyView& v) {
//     return clips::PolicyChoice{v.wait, "this policy never helps"};
//   });
//   clips::SessionOptions o;
//   o.assistance = clips::parse_assistance("idle");
//
// Register at start-up, before sessions run (the table is not locked). A
// policy's own settings are options registered beside it (register_option).
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "clips/types.hpp"

namespace clips {

// What the policy sees at one of the assistant's turns.
struct PolicyView {
  std::vector<std::string> actions;  // the actions it may take now (PDDL text)
  std::string wait;                  // its no-op among them
  // The candidate goals as PDDL conditions and their posterior weights
  // (summed over cost profiles), in the session's order.
  std::vector<std::string> goals;
  std::vector<double> goal_weights;
  // What the last instruction may have asked for (display form), with
  // P(command | instruction) summed over the goals weighted by the posterior.
  std::vector<std::string> asked;
  std::vector<double> asked_weights;
  std::string state;     // the state's atoms, as text
  int t = 0;             // the model time step
  bool stalled = false;  // both agents just waited
  // Every registered option's value (register_option below), as text.
  std::map<std::string, std::string> options;
};

struct PolicyChoice {
  std::string action;  // one of PolicyView::actions
  std::string reason;  // why, in words ("": a default naming the policy)
};

using PolicyFunction = std::function<PolicyChoice(const PolicyView&)>;

// Registers `decide` under `name` (one word, no '/'); returns its value for
// SessionOptions::assistance. InputError for a name that is taken or
// malformed. A choice that is not one of the view's actions, or an exception
// from `decide`, is an InputError naming the policy when the session decides.
Assistance register_policy(const std::string& name, const std::string& help, PolicyFunction decide);
// Takes back a policy register_policy registered; InputError for another name.
void unregister_policy(const std::string& name);

// An option of one's own, for a policy to read (PolicyView::options). Once
// registered it is a session option (SessionOptions::registered_options,
// checked when a session opens), a keyword of Python's sessions, a field of
// the server's "inference" object and of the OpenAPI document it serves
// (GET /api/openapi.json), and a flag --NAME ('-' for '_') of `clips infer`,
// `bench` and `serve` built after it in the same process:
//
//   clips::register_option({"caution", clips::OptionSpec::Kind::Real,
//                           "how sure the policy must be before it acts", "0.8", 0.0, 1.0});
//   clips::SessionOptions o;
//   o.registered_options["caution"] = "0.9";
struct OptionSpec {
  enum class Kind { Integer, Real, Choice };
  std::string name;  // lower-case letters, digits and '_'
  Kind kind = Kind::Real;
  std::string help;
  std::string default_value;               // as text: "0.8", "12", "cautious"
  std::optional<double> minimum, maximum;  // Integer and Real: the range (unset: unbounded)
  std::vector<std::string> choices;        // Choice: its values
};
// InputError for a malformed or taken name (the session's options and the
// arguments of Python's openers included), bounds that are not finite, a
// default outside the range or choices. A CLI command that has a flag of the
// same name keeps its own.
void register_option(const OptionSpec& spec);
// Takes back an option register_option registered; InputError for another name.
void unregister_option(const std::string& name);

}  // namespace clips
