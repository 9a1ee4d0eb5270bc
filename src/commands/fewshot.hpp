#pragma once
// Few-shot examples and prompt strings.
//
// The examples come from a TSV file with the header
//   domain<TAB>index<TAB>command<TAB>utterance<TAB>in_literal_prompt
// (index = position in the reference's source list). Which examples a prompt
// uses, and in which order, is a list of those indices (prompt-orders.json).
// A prompt is the examples as "Input: <command>\nOutput: <utterance>" joined by
// "\n", then "\nInput: <command text>\nOutput:"; the scored continuation is
// " " + utterance + "\n".
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "commands/command.hpp"

namespace clips::commands {

struct FewShotExample {
  std::string domain;
  int index = 0;
  std::string command;    // inserted verbatim after "Input: "
  std::string utterance;  // inserted verbatim after "Output: "
  bool in_literal_prompt = false;
};

// Parses the TSV text; errors are clips::InputError "<source>:<line>: ...".
std::vector<FewShotExample> parse_fewshot_examples(std::string_view text, const std::string& source_name);
std::vector<FewShotExample> load_fewshot_examples(const std::filesystem::path& path);

// The examples of `domain` listed by TSV index in prompt order. Throws
// clips::InputError if an index has no example in that domain.
std::vector<FewShotExample> order_examples(const std::vector<FewShotExample>& examples, std::string_view domain,
                                           const std::vector<int>& order);

struct PromptOrders {
  std::vector<int> pragmatic;  // CLIPS speaker model
  std::vector<int> literal;    // literal listener
};
// {"<domain>": {"pragmatic": [14, 13, ...], "literal": [9, 12, ...]}, ...}
std::map<std::string, PromptOrders> parse_prompt_orders(const std::string& json_text, const std::string& source_name);
std::map<std::string, PromptOrders> load_prompt_orders(const std::filesystem::path& path);

// The prompt for a command whose LLM form is `command_text`.
std::string build_prompt(const std::vector<FewShotExample>& examples, std::string_view command_text);
// The prompt used, with weight 1, when a hypothesis has no command at all.
inline constexpr std::string_view kEmptyCommandPrompt = "\n";
// " " + utterance + "\n"; the leading space is added only if missing.
std::string utterance_continuation(std::string_view utterance);

struct WeightedPrompt {
  std::string prompt;
  double weight = 0.0;
};
// One prompt per command with weight 1/|C|, or the single empty-command prompt
// with weight 1 if there is no command.
std::vector<WeightedPrompt> command_prompts(const std::vector<Command>& commands,
                                            const std::vector<FewShotExample>& examples);

}  // namespace clips::commands
