// The name table of clips::Method (engine/methods.hpp); clips::Assistance's is
// the decision policies' (engine/policies.cpp).
#include "engine/methods.hpp"

namespace clips {

namespace engine {

util::Choices<Method>& method_choices() {
  static util::Choices<Method> table(
      "method",
      {
          {Method::Clips, "clips", "actions and utterances: the paper's CLIPS", {"both"}},
          {Method::LanguageOnly, "lang_only", "utterances only (the actions still move the state)",
           {"utterance", "language", "language-only", "language_only"}},
          {Method::ActionOnly, "action_only", "actions only", {"action", "action-only"}},
          {Method::Literal, "literal",
           "the literal listener: the most probable command of the latest instruction, on the CLIPS posterior",
           {}},
      });
  return table;
}

std::vector<std::string> posterior_method_names() {
  std::vector<std::string> out;
  for (const auto& c : method_choices().entries())
    if (c.value != Method::Literal) out.push_back(c.name);
  return out;
}

}  // namespace engine

std::string method_name(Method m) { return engine::method_choices().name(m); }
Method parse_method(const std::string& text) { return engine::method_choices().parse(text); }
std::vector<std::string> method_names() { return engine::method_choices().names(); }

std::string assistance_name(Assistance a) { return engine::assistance_choices().name(a); }
std::string assistance_help(Assistance a) { return engine::assistance_choices().help(a); }
Assistance parse_assistance(const std::string& text) { return engine::assistance_choices().parse(text); }
std::vector<std::string> assistance_names() { return engine::assistance_choices().names(); }

}  // namespace clips
