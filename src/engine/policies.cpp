// The decision policies' one table (engine/policies.hpp): Q_MDP and pi-bar
// are registered here like any other.
#include "engine/policies.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/methods.hpp"
#include "util/error.hpp"

namespace clips::engine {

namespace {

// Q_MDP's two bench evaluations go by its name and the episode kind (none
// before Q_MDP is registered).
std::vector<std::string> reserved(const util::Choices<Assistance>& names) {
  for (const auto& e : names.entries())
    if (e.value == Assistance::QMdp) return {e.name + "_offline", e.name + "_online"};
  return {};
}

struct Registry {
  util::Choices<Assistance> names{"assistance", {}};
  std::map<Assistance, Decide> decide;

  void add(DecisionPolicy p) {
    if (!p.decide) throw std::logic_error("assistance '" + p.name + "' needs a decide()");
    if (decide.count(p.value)) throw std::logic_error("assistance '" + p.name + "': its value is registered twice");
    for (const std::string& taken : reserved(names))
      if (p.name == taken) throw std::logic_error("assistance '" + p.name + "' is the name of a bench evaluation");
    names.add({p.value, p.name, p.help, {}});
    decide.emplace(p.value, std::move(p.decide));
  }
};

Registry& registry() {
  static Registry r = [] {
    Registry out;
    out.add({Assistance::QMdp, "qmdp", "Q_MDP: the action of highest posterior-weighted Q-value, as in the paper",
             [](const DecisionInput& in) {
               return assist::qmdp_decision(in.setup, in.hypotheses, in.state, in.t, in.stalled,
                                            in.since_instruction);
             }});
    out.add({Assistance::PiBar, "pibar", "pi-bar_MDP: the action the posterior mixture of policies takes most often",
             [](const DecisionInput& in) { return assist::pibar_decision(in.setup, in.hypotheses, in.state); }});
    return out;
  }();
  return r;
}

}  // namespace

const util::Choices<Assistance>& assistance_choices() { return registry().names; }

void register_assistance(DecisionPolicy policy) { registry().add(std::move(policy)); }

void unregister_assistance(const std::string& name) {
  Registry& r = registry();
  for (const auto& e : r.names.entries())
    if (e.name == name) {
      r.decide.erase(e.value);
      r.names.remove(name);
      return;
    }
}

const Decide& decide_of(Assistance a) {
  const Registry& r = registry();
  const auto it = r.decide.find(a);
  if (it == r.decide.end())
    throw InputError("no decision policy has the value " + std::to_string(static_cast<int>(a)) + " (known: " +
                     util::or_list(r.names.names()) + ")");
  return it->second;
}

std::vector<std::string> reserved_policy_names() { return reserved(registry().names); }

}  // namespace clips::engine
