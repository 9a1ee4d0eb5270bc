#pragma once
// Builds the CLIPS few-shot prompts (clips-spec 7.7) from data/language/fewshot-examples.tsv
// for the embedded-LM tests.
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace clips::lm::testing {

struct FewShot {
  std::string command;
  std::string utterance;
};

inline std::map<std::pair<std::string, int>, FewShot> load_fewshot() {
  const std::string path = std::string(CLIPS_SOURCE_DIR) + "/data/language/fewshot-examples.tsv";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::map<std::pair<std::string, int>, FewShot> out;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, '\t')) f.push_back(field);
    if (f.size() < 4) continue;
    out[{f[0], std::stoi(f[1])}] = FewShot{f[2], f[3]};
  }
  return out;
}

inline std::string fewshot_block(const std::string& domain, const std::vector<int>& order) {
  static const auto examples = load_fewshot();
  std::string block;
  for (size_t i = 0; i < order.size(); ++i) {
    const FewShot& e = examples.at({domain, order[i]});
    if (i > 0) block += "\n";
    block += "Input: " + e.command + "\nOutput: " + e.utterance;
  }
  return block;
}

inline const std::vector<int>& literal_order() {
  static const std::vector<int> o = {9, 12, 2, 11, 6, 5, 3, 8, 10, 1, 7, 4};
  return o;
}
inline const std::vector<int>& pragmatic_order() {
  static const std::vector<int> o = {14, 13, 15, 7, 10, 3, 2, 16, 5, 12, 6, 8, 9, 4, 18, 11, 17, 1};
  return o;
}
inline const std::vector<int>& vh_order() {
  static const std::vector<int> o = {5, 7, 2, 9, 4, 8, 11, 12, 6, 10, 3, 1};
  return o;
}

inline std::string literal_prompt(const std::string& command) {
  return fewshot_block("doors-keys-gems", literal_order()) + "\nInput: " + command + "\nOutput:";
}
inline std::string pragmatic_prompt(const std::string& command) {
  return fewshot_block("doors-keys-gems", pragmatic_order()) + "\nInput: " + command + "\nOutput:";
}
inline std::string vh_prompt(const std::string& command) {
  return fewshot_block("virtual-home", vh_order()) + "\nInput: " + command + "\nOutput:";
}

}  // namespace clips::lm::testing
