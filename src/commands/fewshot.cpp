#include "commands/fewshot.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands/term.hpp"
#include "util/error.hpp"

namespace clips::commands {

namespace {

constexpr std::string_view kHeader = "domain\tindex\tcommand\tutterance\tin_literal_prompt";

std::string read_file(const std::filesystem::path& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLoc{path.string(), 0, 0}, "cannot open " + what);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Why a command's text is not "(action args...) ... [where (pred args...) ...]"
// ("" when it is): said here, with the file and line, rather than when a
// language model first reads the prompt.
std::string command_syntax_problem(const std::string& command) {
  const size_t where = command.find(" where ");
  try {
    if (parse_terms(std::string_view(command).substr(0, where)).empty()) return "no action before 'where'";
    if (where != std::string::npos && parse_terms(std::string_view(command).substr(where + 7)).empty())
      return "no condition after 'where'";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::vector<std::string> split_tabs(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t tab = line.find('\t', start);
    fields.emplace_back(line.substr(start, tab == std::string_view::npos ? std::string_view::npos : tab - start));
    if (tab == std::string_view::npos) return fields;
    start = tab + 1;
  }
}

}  // namespace

std::vector<FewShotExample> parse_fewshot_examples(std::string_view text, const std::string& source_name) {
  std::vector<FewShotExample> examples;
  std::set<std::pair<std::string, int>> seen;
  int line_number = 0;
  bool header_seen = false;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const auto fail = [&](const std::string& why) { throw InputError(SourceLoc{source_name, line_number, 0}, why); };

    if (!header_seen) {
      if (line != kHeader)
        fail("expected the header 'domain<TAB>index<TAB>command<TAB>utterance<TAB>in_literal_prompt'");
      header_seen = true;
      continue;
    }
    if (line.empty()) continue;

    const auto fields = split_tabs(line);
    if (fields.size() != 5)
      fail("expected 5 tab-separated fields, found " + std::to_string(fields.size()));
    FewShotExample ex;
    ex.domain = fields[0];
    if (ex.domain.empty()) fail("empty domain");
    const std::string& index = fields[1];
    const auto [ptr, ec] = std::from_chars(index.data(), index.data() + index.size(), ex.index);
    if (ec != std::errc() || ptr != index.data() + index.size() || ex.index < 1)
      fail("index '" + index + "' is not a positive integer");
    ex.command = fields[2];
    if (ex.command.empty()) fail("empty command");
    if (const std::string why = command_syntax_problem(ex.command); !why.empty())
      fail("command '" + ex.command + "': " + why);
    ex.utterance = fields[3];
    if (ex.utterance.empty()) fail("empty utterance");
    if (fields[4] == "yes")
      ex.in_literal_prompt = true;
    else if (fields[4] != "no")
      fail("in_literal_prompt must be 'yes' or 'no', found '" + fields[4] + "'");
    if (!seen.insert({ex.domain, ex.index}).second)
      fail("duplicate example " + ex.domain + " #" + std::to_string(ex.index));
    examples.push_back(std::move(ex));
  }
  if (!header_seen) throw InputError(SourceLoc{source_name, 1, 0}, "empty file, expected a header line");
  return examples;
}

std::vector<FewShotExample> load_fewshot_examples(const std::filesystem::path& path) {
  return parse_fewshot_examples(read_file(path, "few-shot examples"), path.string());
}

std::vector<FewShotExample> order_examples(const std::vector<FewShotExample>& examples, std::string_view domain,
                                           const std::vector<int>& order) {
  std::vector<FewShotExample> ordered;
  for (int index : order) {
    auto it = std::find_if(examples.begin(), examples.end(),
                           [&](const FewShotExample& ex) { return ex.domain == domain && ex.index == index; });
    if (it == examples.end())
      throw InputError("no few-shot example #" + std::to_string(index) + " for domain '" + std::string(domain) + "'");
    ordered.push_back(*it);
  }
  return ordered;
}

std::map<std::string, PromptOrders> parse_prompt_orders(const std::string& json_text, const std::string& source_name) {
  const auto fail = [&](const std::string& key, const std::string& why) {
    throw InputError(SourceLoc{source_name, 0, 0}, key + ": " + why);
  };
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for a number too large
    fail("(top level)", std::string("invalid JSON: ") + e.what());
  }
  if (!doc.is_object()) fail("(top level)", "expected an object of domain -> orders");

  const auto read_list = [&](const nlohmann::json& entry, const std::string& domain, const char* name) {
    const std::string key = domain + "." + name;
    if (!entry.contains(name)) fail(key, "missing");
    const auto& list = entry[name];
    if (!list.is_array() || list.empty()) fail(key, "expected a non-empty array of example indices");
    std::vector<int> order;
    for (const auto& v : list) {
      if (!v.is_number_integer() || v.get<long long>() < 1) fail(key, "indices must be positive integers");
      const int index = v.get<int>();
      if (std::find(order.begin(), order.end(), index) != order.end())
        fail(key, "index " + std::to_string(index) + " repeated");
      order.push_back(index);
    }
    return order;
  };

  std::map<std::string, PromptOrders> orders;
  for (const auto& [domain, entry] : doc.items()) {
    if (domain == "comment") continue;
    if (!entry.is_object()) fail(domain, "expected {\"pragmatic\": [...], \"literal\": [...]}");
    orders[domain] = PromptOrders{read_list(entry, domain, "pragmatic"), read_list(entry, domain, "literal")};
  }
  return orders;
}

std::map<std::string, PromptOrders> load_prompt_orders(const std::filesystem::path& path) {
  return parse_prompt_orders(read_file(path, "prompt orders"), path.string());
}

std::string build_prompt(const std::vector<FewShotExample>& examples, std::string_view command_text) {
  std::string prompt;
  for (std::size_t i = 0; i < examples.size(); ++i) {
    if (i > 0) prompt += '\n';
    prompt += "Input: " + examples[i].command + "\nOutput: " + examples[i].utterance;
  }
  prompt += "\nInput: ";
  prompt += command_text;
  prompt += "\nOutput:";
  return prompt;
}

std::string utterance_continuation(std::string_view utterance) {
  std::string text;
  if (utterance.empty() || utterance.front() != ' ') text = " ";
  text += utterance;
  text += '\n';
  return text;
}

std::vector<WeightedPrompt> command_prompts(const std::vector<Command>& commands,
                                            const std::vector<FewShotExample>& examples) {
  if (commands.empty()) return {WeightedPrompt{std::string(kEmptyCommandPrompt), 1.0}};
  std::vector<WeightedPrompt> prompts;
  const double weight = 1.0 / static_cast<double>(commands.size());
  for (const auto& cmd : commands) prompts.push_back({build_prompt(examples, cmd.llm_form()), weight});
  return prompts;
}

}  // namespace clips::commands
