#include "engine/choices.hpp"

#include "assist/assist.hpp"
#include "domains/pack.hpp"
#include "engine/methods.hpp"
#include "heuristics/registry.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"

namespace clips::engine {

util::ChoiceCatalogue choice_catalogue() {
  return {
      {"method", method_choices().info()},
      {"assistance", assistance_choices().info()},
      {"modality", inference::modality_choices().info()},
      {"assistant_turns", inference::assistant_turns_choices().info()},
      {"speaker_rule", inference::speaker_rule_choices().info()},
      {"speaker_plans", domains::speaker_plans_choices().info()},
      {"utterance_timing", inference::utterance_timing_choices().info()},
      {"qa_floor", assist::qa_floor_choices().info()},
      {"assist_rule", assist::assist_rule_choices().info()},
      {"rejuvenate", inference::rejuvenation_choices().info()},
      {"particle_filters", inference::particle_filters_choices().info()},
      {"particle_estimate", inference::particle_estimate_choices().info()},
      {"heuristic", heuristics::generic_heuristic_choices().info()},
      {"lm", language::language_model_choices().info()},
  };
}

}  // namespace clips::engine
