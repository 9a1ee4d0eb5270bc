#pragma once
// The name tables of clips::Method and clips::Assistance (include/clips/types.hpp
// declares the enums and the name functions the public API keeps): the CLI's
// flags, Python's keywords, the server's fields and its OpenAPI enums read
// these (util/choices.hpp).
#include "clips/types.hpp"
#include "util/choices.hpp"

namespace clips::engine {

util::Choices<Method>& method_choices();
// The decision policies' names: each registered once with its decide()
// (engine/policies.hpp).
const util::Choices<Assistance>& assistance_choices();
// The methods with a posterior of their own (all but literal, which reads the
// CLIPS one): `clips infer --modalities`, the bench's inference methods.
std::vector<std::string> posterior_method_names();

}  // namespace clips::engine
