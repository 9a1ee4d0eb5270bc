// Decision policies of the library's users (include/clips/policy.hpp): a
// PolicyFunction wrapped as an engine decide() and registered in the one
// table of decision policies (engine/policies.hpp). Python's register_policy
// is this function with a Python callable.
#include "clips/policy.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <set>

#include "engine/methods.hpp"
#include "engine/options.hpp"
#include "engine/policies.hpp"
#include "util/choices.hpp"
#include "util/error.hpp"

namespace clips {

namespace {

std::mutex& registered_mutex() {
  static std::mutex m;
  return m;
}
std::set<std::string>& registered() {
  static std::set<std::string> names;
  return names;
}

PolicyView view_of(const engine::DecisionInput& in, const std::vector<pddl::ActionId>& candidates) {
  const pddl::Task& task = *in.setup.task;
  PolicyView v;
  for (pddl::ActionId a : candidates) v.actions.push_back(task.action_name(a));
  v.wait = task.action_name(in.setup.turns().noop(task, in.setup.assistant));
  // Several cost profiles share a goal, and several goals a reading: summed.
  auto add = [](std::vector<std::string>& keys, std::vector<double>& weights, const std::string& key, double w) {
    const auto it = std::find(keys.begin(), keys.end(), key);
    if (it != keys.end()) {
      weights[static_cast<size_t>(it - keys.begin())] += w;
      return;
    }
    keys.push_back(key);
    weights.push_back(w);
  };
  for (const auto& h : in.hypotheses) {
    add(v.goals, v.goal_weights, h.policy->spec().goal_text(), h.weight);
    if (h.request)
      for (const auto& c : *h.request) add(v.asked, v.asked_weights, c.text, h.weight * c.probability);
  }
  v.state = task.state_str(in.state);
  v.t = in.t;
  v.stalled = in.stalled;
  v.options = in.setup.registered_options;
  return v;
}

}  // namespace

Assistance register_policy(const std::string& name, const std::string& help, PolicyFunction decide) {
  if (name.empty() || name.find_first_of(" /\t\r\n") != std::string::npos)
    throw InputError("a policy's name is one word without '/' (the bench writes METHOD/NAME), got '" + name + "'");
  if (!decide) throw InputError("policy '" + name + "': no decide function");
  const auto& table = engine::assistance_choices();
  const auto reserved = engine::reserved_policy_names();
  if (table.contains(name) || std::find(reserved.begin(), reserved.end(), name) != reserved.end())
    throw InputError("the assistance policy '" + name + "' is already registered (taken: " +
                     util::or_list(table.names()) + ", and the bench's " + util::or_list(reserved) + ")");
  int value = 1000;  // the built-in policies' values are small
  for (const auto& e : table.entries()) value = std::max(value, static_cast<int>(e.value) + 1);
  const auto a = static_cast<Assistance>(value);
  engine::register_assistance(
      {a, name, help, [name, decide = std::move(decide)](const engine::DecisionInput& in) {
         assist::Decision d;
         d.candidates = in.setup.task->applicable_actions(in.state);
         if (d.candidates.empty()) throw InputError("no action is applicable in the assistance state");
         const PolicyView v = view_of(in, d.candidates);
         PolicyChoice choice;
         try {
           choice = decide(v);
         } catch (const InputError&) {
           throw;
         } catch (const std::exception& e) {
           throw InputError("assistance policy '" + name + "' raised " + e.what());
         }
         const auto it = std::find(v.actions.begin(), v.actions.end(), choice.action);
         if (it == v.actions.end())
           throw InputError("assistance policy '" + name + "' returned '" + choice.action +
                            "', which is not an applicable action (" + util::or_list(v.actions) + ")");
         const size_t i = static_cast<size_t>(it - v.actions.begin());
         d.action = d.candidates[i];
         d.values.assign(d.candidates.size(), 0.0);
         d.values[i] = 1.0;
         d.reason = choice.reason.empty() ? "the policy '" + name + "' chose it" : choice.reason;
         return d;
       }});
  std::lock_guard<std::mutex> lock(registered_mutex());
  registered().insert(name);
  return a;
}

void unregister_policy(const std::string& name) {
  {
    std::lock_guard<std::mutex> lock(registered_mutex());
    if (registered().erase(name) == 0)
      throw InputError("'" + name + "' is not a policy registered with register_policy");
  }
  engine::unregister_assistance(name);
}

}  // namespace clips

namespace clips {

void register_option(const OptionSpec& spec) {
  engine::EngineOption o;
  o.name = spec.name;
  o.kind = spec.kind == OptionSpec::Kind::Integer ? engine::EngineOption::Kind::Integer
           : spec.kind == OptionSpec::Kind::Real  ? engine::EngineOption::Kind::Real
                                                  : engine::EngineOption::Kind::Choice;
  o.help = spec.help;
  o.default_text = spec.default_value;
  o.minimum = spec.minimum;
  o.maximum = spec.maximum;
  o.choices = spec.choices;
  engine::register_option(std::move(o));
}

void unregister_option(const std::string& name) { engine::unregister_option(name); }

}  // namespace clips
