#include "language/lm/embedded_model.hpp"

#include <cstdlib>
#include <fstream>
#include <shared_mutex>
#include <unordered_map>

#include "language/lm/alignment_model.hpp"
#include "language/lm/command_frame.hpp"

namespace clips::lm {
namespace {

std::string default_data_dir() {
  if (const char* env = std::getenv("CLIPS_DATA_DIR"); env != nullptr && *env != '\0') return env;
#ifdef CLIPS_SOURCE_DIR
  return std::string(CLIPS_SOURCE_DIR) + "/data/language";
#else
  return "data/language";
#endif
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::vector<TrainingPair> read_corpus(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw LmError("embedded LM: cannot open corpus file " + path);
  std::vector<TrainingPair> out;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string origin = path + ":" + std::to_string(number);
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const size_t tab = line.find('\t');
    if (tab == std::string::npos) {
      throw LmError("embedded LM: " + origin + ": expected \"command<TAB>utterance\"");
    }
    TrainingPair p;
    p.command = trim(line.substr(0, tab));
    p.utterance = trim(line.substr(tab + 1));
    p.origin = origin;
    if (p.command.empty() || p.utterance.empty() || p.command[0] != '(') {
      throw LmError("embedded LM: " + origin + ": empty utterance or command not starting with '('");
    }
    if (p.utterance.find('\t') != std::string::npos) {
      throw LmError("embedded LM: " + origin + ": more than two tab-separated fields");
    }
    parse_command_frame(p.command, origin);  // validate now, with file and line
    out.push_back(std::move(p));
  }
  if (out.empty()) throw LmError("embedded LM: corpus file " + path + " holds no pairs");
  return out;
}

}  // namespace

std::pair<std::string, std::string> split_prompt(const std::string& prompt) {
  static const std::string kInput = "Input: ";
  static const std::string kOutput = "\nOutput:";
  if (prompt.find(kInput) == std::string::npos && trim(prompt).empty()) return {"", ""};
  if (prompt.size() < kOutput.size() ||
      prompt.compare(prompt.size() - kOutput.size(), kOutput.size(), kOutput) != 0) {
    throw LmError("embedded LM: prompt does not end with \"\\nOutput:\" (prompt starts \"" +
                  prompt.substr(0, 60) + "\")");
  }
  const size_t body_end = prompt.size() - kOutput.size();
  size_t input = prompt.rfind("\n" + kInput, body_end);
  size_t cmd_start;
  std::string block;
  if (input == std::string::npos) {
    if (prompt.compare(0, kInput.size(), kInput) != 0) {
      throw LmError("embedded LM: prompt has no \"Input: \" line before the final \"Output:\"");
    }
    cmd_start = kInput.size();
  } else {
    cmd_start = input + 1 + kInput.size();
    block = prompt.substr(0, input);
  }
  return {block, trim(prompt.substr(cmd_start, body_end - cmd_start))};
}

std::vector<std::pair<std::string, std::string>> parse_fewshot_block(const std::string& block) {
  std::vector<std::pair<std::string, std::string>> out;
  size_t pos = 0;
  std::string pending_cmd;
  bool have_cmd = false;
  while (pos <= block.size()) {
    size_t nl = block.find('\n', pos);
    if (nl == std::string::npos) nl = block.size();
    const std::string line = block.substr(pos, nl - pos);
    pos = nl + 1;
    if (line.rfind("Input:", 0) == 0) {
      pending_cmd = trim(line.substr(6));
      have_cmd = true;
    } else if (line.rfind("Output:", 0) == 0 && have_cmd) {
      out.emplace_back(pending_cmd, trim(line.substr(7)));
      have_cmd = false;
    }
    if (nl == block.size()) break;
  }
  return out;
}

struct EmbeddedLanguageModel::BlockState {
  std::shared_ptr<AlignmentModel> model;
  std::shared_mutex mutex;
  std::unordered_map<std::string, std::shared_ptr<const AlignmentModel::Bound>> frames;

  std::shared_ptr<const AlignmentModel::Bound> frame(const std::string& command) {
    {
      std::shared_lock lock(mutex);
      auto it = frames.find(command);
      if (it != frames.end()) return it->second;
    }
    auto b = model->bind(command);
    std::unique_lock lock(mutex);
    return frames.emplace(command, std::move(b)).first->second;
  }
};

EmbeddedLanguageModel::EmbeddedLanguageModel(const std::string& data_dir)
    : EmbeddedLanguageModel([&] {
        EmbeddedModelOptions o;
        o.data_dir = data_dir;
        return o;
      }()) {}

EmbeddedLanguageModel::EmbeddedLanguageModel(EmbeddedModelOptions options)
    : options_(std::move(options)) {
  data_dir_ = options_.data_dir.empty() ? default_data_dir() : options_.data_dir;
  for (const std::string& f : options_.corpus_files) {
    auto pairs = read_corpus(data_dir_ + "/" + f);
    corpus_.insert(corpus_.end(), pairs.begin(), pairs.end());
  }
}

EmbeddedLanguageModel::~EmbeddedLanguageModel() = default;

size_t EmbeddedLanguageModel::trained_blocks() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return blocks_.size();
}

std::shared_ptr<EmbeddedLanguageModel::BlockState> EmbeddedLanguageModel::block_state(const std::string& block) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = blocks_.find(block);
  if (it != blocks_.end()) return it->second;
  std::vector<TrainingPair> pairs = corpus_;
  int index = 0;
  for (const auto& [cmd, utt] : parse_fewshot_block(block)) {
    ++index;
    pairs.push_back(TrainingPair{cmd, utt, options_.fewshot_weight, "prompt example " + std::to_string(index)});
  }
  auto state = std::make_shared<BlockState>();
  state->model = AlignmentModel::train(pairs, options_.em_iterations);
  blocks_.emplace(block, state);
  return state;
}

std::shared_ptr<const AlignmentModel> EmbeddedLanguageModel::model_for_prompt(const std::string& prompt) {
  return block_state(split_prompt(prompt).first)->model;
}

double EmbeddedLanguageModel::score_one(const std::string& prompt, const std::string& continuation) {
  const auto [block, command] = split_prompt(prompt);
  auto state = block_state(block);
  const bool complete = !continuation.empty() && continuation.back() == '\n';
  // The empty-command prompt "\n" carries no context: score unprimed.
  if (block.empty() && command.empty()) return state->model->log_prob_unprimed(state->model->encode(continuation), complete);
  auto frame = state->frame(command);
  return state->model->log_prob(*frame, state->model->encode(continuation), complete);
}

std::vector<double> EmbeddedLanguageModel::score(const std::vector<ScoreRequest>& batch) {
  std::vector<double> out;
  out.reserve(batch.size());
  for (const ScoreRequest& r : batch) out.push_back(score_one(r.prompt, r.continuation));
  return out;
}

}  // namespace clips::lm
