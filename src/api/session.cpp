// clips::Session (include/clips/session.hpp): a thin driver over the session
// engine (src/engine), which owns the belief, the decisions and the trace.
#include "clips/session.hpp"
#include "api/session_internals.hpp"

#include "clips/version.hpp"
#include "engine/engine.hpp"
#include "lm/language_model.hpp"
#include "util/data_dir.hpp"

namespace clips {

namespace {

// The language model's failures, as the public error.
template <typename F>
auto lm_errors(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const lm::LmError& e) {
    throw LanguageModelError(e.what());
  }
}

engine::GoalChoice goal_choice(const SessionOptions& o) {
  return {o.goals, "give the candidate goals in SessionOptions::goals"};
}

}  // namespace

struct Session::Impl {
  engine::Engine engine;
};

Session::Session(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Session::Session(Session&&) noexcept = default;
Session& Session::operator=(Session&&) noexcept = default;
Session::~Session() = default;

Session Session::open_dataset(const std::string& dataset_dir, const std::string& problem, SessionOptions options) {
  engine::Problem p = engine::dataset_problem(dataset_dir, problem);
  return Session(std::make_unique<Impl>(Impl{lm_errors([&] { return engine::Engine(std::move(p), std::move(options)); })}));
}

Session Session::open_domain(const std::string& domain_dir, const std::string& problem_file, SessionOptions options) {
  engine::Problem p = engine::domain_problem(domain_dir, problem_file, goal_choice(options));
  return Session(std::make_unique<Impl>(Impl{lm_errors([&] { return engine::Engine(std::move(p), std::move(options)); })}));
}

Session Session::open_domain_text(const std::string& domain_pddl, const std::string& problem_pddl,
                                  const std::string& pack_json, SessionOptions options) {
  engine::Problem p = engine::text_problem(domain_pddl, problem_pddl, pack_json, {}, 0, goal_choice(options));
  return Session(std::make_unique<Impl>(Impl{lm_errors([&] { return engine::Engine(std::move(p), std::move(options)); })}));
}

const Step& Session::observe(const std::string& action) { return observe(action, CallLimits{}); }
const Step& Session::observe(int action_id) { return observe(action_id, CallLimits{}); }
const Step& Session::hear(const std::string& utterance) { return hear(utterance, CallLimits{}); }
AssistDecision Session::assist() { return assist(CallLimits{}); }

const Step& Session::observe(const std::string& action, const CallLimits& limits) {
  return impl_->engine.observe(action, limits);
}

const Step& Session::observe(int action_id, const CallLimits& limits) {
  return impl_->engine.observe(static_cast<pddl::ActionId>(action_id), limits);
}

const Step& Session::hear(const std::string& utterance, const CallLimits& limits) {
  return lm_errors([&]() -> const Step& { return impl_->engine.hear(utterance, limits); });
}

AssistDecision Session::assist(const CallLimits& limits) {
  return lm_errors([&] { return impl_->engine.assist(limits); });
}

bool Session::undo(const CallLimits& limits) {
  return lm_errors([&] { return impl_->engine.undo(limits); });
}

void Session::reset() { impl_->engine.reset(); }

bool Session::goal_holds(const std::string& goal) const { return impl_->engine.goal_holds(goal); }

Posterior Session::posterior() const { return impl_->engine.posterior(); }

Posterior Session::posterior(Method method) const { return impl_->engine.posterior(method); }

int Session::t() const { return impl_->engine.t(); }

std::string Session::state() const { return impl_->engine.pack().describe_state(impl_->engine.task(), impl_->engine.state()); }

const std::vector<Step>& Session::trace() const { return impl_->engine.trace(); }

std::string Session::domain() const { return impl_->engine.pack().name(); }

bool Session::assistant_turn() const { return impl_->engine.assistant_turn(); }

std::string Session::active_agent() const { return impl_->engine.active_agent(); }

std::vector<CandidateAction> Session::applicable_actions() const { return impl_->engine.applicable_actions(); }

std::string Session::action_name(int action_id) const {
  if (action_id < 0 || action_id >= impl_->engine.task().num_actions())
    throw InputError("action id " + std::to_string(action_id) + " is out of range");
  return impl_->engine.task().action_name(action_id);
}

std::string library_version() { return CLIPS_VERSION_STRING; }

std::string data_directory() { return util::data_dir(); }

const pddl::Task& SessionInternals::task(const Session& s) { return s.impl_->engine.task(); }
const pddl::State& SessionInternals::state(const Session& s) { return s.impl_->engine.state(); }
const domains::Pack& SessionInternals::pack(const Session& s) { return s.impl_->engine.pack(); }
std::vector<std::pair<bool, std::string>> SessionInternals::events(const Session& s) {
  std::vector<std::pair<bool, std::string>> out;
  for (const auto& e : s.impl_->engine.events()) out.emplace_back(e.utterance, e.text);
  return out;
}

}  // namespace clips
