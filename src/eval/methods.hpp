#pragma once
// The methods `clips bench` compares, as objects behind one interface: each
// takes the plan's shared work (one inference run in three modalities, the
// assistance set-up, the true specification) and fills in its result row.
// Their names come from the name tables (util/choices.hpp):
//
//   clips | lang_only | action_only          inference in one modality
//     (engine::posterior_method_names), then
//     [/qmdp_online | /pibar]                an assistance policy
//     (assist_policy_choices; the first, qmdp_offline, is the default and
//     leaves the name bare)
//   literal_efficient | literal_naive | literal   the literal listener
//     (domains::literal_method_choices)
//   multimodal                                    a multimodal chat model (issue 8)
//     (baseline_choices)
//
// Method names are an interface (results.csv, summary.json): keep them stable.
#include <memory>
#include <string>
#include <vector>

#include "assist/assist.hpp"
#include "clips/types.hpp"
#include "data/dataset.hpp"
#include "multimodal/multimodal.hpp"
#include "inference/belief.hpp"
#include "lm/language_model.hpp"
#include "util/choices.hpp"

namespace clips::eval {

struct MethodResult;
struct ExperimentOptions;

// What every method of one plan shares: computed once by evaluate_plan.
struct PlanContext {
  const data::Dataset& dataset;
  const data::PlanRecord& plan;
  lm::LanguageModel& lm;
  const ExperimentOptions& options;
  std::shared_ptr<const pddl::Task> task;
  const inference::InferenceRun& inference;
  int true_hypothesis = -1;
  std::shared_ptr<const model::Specification> true_spec;
  const assist::AssistSetup& setup;  // the assistance episode from s_T
  const std::vector<std::string>& true_options;  // what the completed plan's assistant did
};

class Method {
 public:
  virtual ~Method() = default;
  const std::string& name() const { return name_; }
  // Fills in `r` (goal posterior, assistance run); throws on input errors.
  virtual void run(const PlanContext& ctx, MethodResult& r) const = 0;

 protected:
  explicit Method(std::string name) : name_(std::move(name)) {}

 private:
  std::string name_;
};

// How an inference method's assistant acts over the episode: the part after
// the slash of "clips/pibar". The first entry is the default.
//   qmdp_offline, qmdp_online: the live Q_MDP policy's decide() at each
//     assistant turn, on the posterior after the observations (the paper's)
//     or on one updated by each action of the episode;
//   pibar: the paper's pi-bar_MDP evaluation (assist::pibar_mdp);
//   every other decision policy registered for the live sessions
//   (engine::register_assistance), under its own name: its decide() at each
//   turn, offline. So registering a policy makes it a bench method too.
enum class Episodes { Offline, Online, PaperMixture };
struct AssistPolicy {
  Assistance decide = Assistance::QMdp;
  Episodes episodes = Episodes::Offline;
  bool operator==(const AssistPolicy&) const = default;
};
// Read-only: it follows the decision policies' table on every call.
const util::Choices<AssistPolicy>& assist_policy_choices();
// Which policies `clips bench --assist` runs: the default one alone (each
// inference method's bare name) or every one (adds "clips/pibar", ...).
enum class AssistanceSet { Default, All };
util::Choices<AssistanceSet>& assistance_set_choices();
// Methods that are neither inference nor the literal listener.
enum class Baseline { Multimodal };
util::Choices<Baseline>& baseline_choices();
// "clips/pibar"; the bare base for the default policy.
std::string composite_method_name(const std::string& base, AssistPolicy policy);
// Every method name make_method accepts, inference methods with each policy.
std::vector<std::string> all_method_names();

// The method of a name (see above); InputError for an unknown one.
std::unique_ptr<Method> make_method(const std::string& name);

// The assistance run's metrics and actions into a result row.
void score_assistance(const PlanContext& ctx, const assist::AssistResult& a, MethodResult& r);

}  // namespace clips::eval
