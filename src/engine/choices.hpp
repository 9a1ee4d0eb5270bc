#pragma once
// The catalogue of the session's named choices (util/choices.hpp): every kind
// the session API, the server and Python offer, by the name of the field or
// keyword that takes it. eval::choice_catalogue adds the bench's kinds.
#include "util/choices.hpp"

namespace clips::engine {

util::ChoiceCatalogue choice_catalogue();

}  // namespace clips::engine
