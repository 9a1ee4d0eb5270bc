#pragma once
// Every named choice of every front end: the session's (engine::choice_catalogue)
// and the bench's (its assistance policies, literal listeners, baselines).
// docs/cli.md's "Named choices" table is made from it (choices_markdown) and
// a test keeps the page equal to it.
#include <string>

#include "util/choices.hpp"

namespace clips::eval {

util::ChoiceCatalogue choice_catalogue();
// The Markdown table of the catalogue: | choice | name | what it does |.
std::string choices_markdown();

}  // namespace clips::eval
