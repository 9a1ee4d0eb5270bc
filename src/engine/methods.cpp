// The name tables of clips::Method and clips::Assistance
// (include/clips/types.hpp): CLI flags, Python keywords and JSON fields all
// read and write these names.
#include <array>

#include "clips/types.hpp"
#include "util/error.hpp"

namespace clips {

namespace {

struct MethodNames {
  Method method;
  const char* name;                      // canonical
  std::array<const char*, 4> aliases;    // older spellings, still read
};

constexpr std::array<MethodNames, 4> kTable = {{
    {Method::Clips, "clips", {"both", "", "", ""}},
    {Method::LanguageOnly, "lang_only", {"utterance", "language", "language-only", "language_only"}},
    {Method::ActionOnly, "action_only", {"action", "action-only", "", ""}},
    {Method::Literal, "literal", {"", "", "", ""}},
}};

}  // namespace

std::string method_name(Method m) {
  for (const auto& row : kTable)
    if (row.method == m) return row.name;
  throw InputError("unknown method");
}

Method parse_method(const std::string& text) {
  for (const auto& row : kTable) {
    if (text == row.name) return row.method;
    for (const char* a : row.aliases)
      if (*a && text == a) return row.method;
  }
  throw InputError("unknown method '" + text + "' (known: clips, lang_only, action_only, literal; also read: both, "
                   "utterance, language, action)");
}

const std::vector<std::string>& method_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& row : kTable) n.push_back(row.name);
    return n;
  }();
  return names;
}

namespace {

struct AssistanceNames {
  Assistance assistance;
  const char* name;
  const char* help;
};

constexpr std::array<AssistanceNames, 2> kAssistanceTable = {{
    {Assistance::QMdp, "qmdp", "Q_MDP: the action of highest posterior-weighted Q-value (the paper's)"},
    {Assistance::PiBar, "pibar", "pi-bar_MDP: the action the posterior mixture of policies takes most often"},
}};

}  // namespace

std::string assistance_name(Assistance a) {
  for (const auto& row : kAssistanceTable)
    if (row.assistance == a) return row.name;
  throw InputError("unknown assistance");
}

std::string assistance_help(Assistance a) {
  for (const auto& row : kAssistanceTable)
    if (row.assistance == a) return row.help;
  throw InputError("unknown assistance");
}

Assistance parse_assistance(const std::string& text) {
  std::string known;
  for (const auto& row : kAssistanceTable) {
    if (text == row.name) return row.assistance;
    known += (known.empty() ? "" : ", ") + std::string(row.name);
  }
  throw InputError("unknown assistance '" + text + "' (known: " + known + ")");
}

const std::vector<std::string>& assistance_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& row : kAssistanceTable) n.push_back(row.name);
    return n;
  }();
  return names;
}

}  // namespace clips
