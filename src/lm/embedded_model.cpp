#include "lm/embedded_model.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <shared_mutex>
#include <sstream>
#include <unordered_map>

#include "lm/alignment_model.hpp"
#include "lm/command_frame.hpp"
#include "util/data_dir.hpp"
#include "util/error.hpp"
#include "util/hash.hpp"

namespace clips::lm {
namespace {

std::string default_data_dir() { return util::data_dir() + "/language"; }

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// A corpus file is input: its errors are InputErrors naming file:line (a
// pack's embedded_corpus names such files).
std::vector<TrainingPair> read_corpus(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError(SourceLoc{path, 0, 0}, "cannot open this embedded-LM corpus file (a pack's embedded_corpus "
                                            "names files of the language data folder)");
  std::vector<TrainingPair> out;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string origin = path + ":" + std::to_string(number);
    const SourceLoc here{path, number, 0};
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const size_t tab = line.find('\t');
    if (tab == std::string::npos) throw InputError(here, "corpus line: expected \"command<TAB>utterance\"");
    TrainingPair p;
    p.command = trim(line.substr(0, tab));
    p.utterance = trim(line.substr(tab + 1));
    p.origin = origin;
    if (p.command.empty() || p.utterance.empty() || p.command[0] != '(')
      throw InputError(here, "corpus line: empty utterance or command not starting with '('");
    if (p.utterance.find('\t') != std::string::npos)
      throw InputError(here, "corpus line: more than two tab-separated fields");
    try {
      parse_command_frame(p.command, origin);  // validate now, with file and line
    } catch (const LmError& e) {
      throw InputError(here, std::string("corpus line: ") + e.what());
    }
    out.push_back(std::move(p));
  }
  if (out.empty()) throw InputError(SourceLoc{path, 0, 0}, "this embedded-LM corpus file holds no pairs");
  return out;
}

// ---- on-disk cache of trained models ------------------------------------------

namespace fs = std::filesystem;

std::string env_or_empty(const char* name) {
  const char* v = std::getenv(name);
  return v == nullptr ? std::string() : std::string(v);
}

std::string resolve_cache_dir(const std::string& option) {
  std::string dir = option.empty() ? env_or_empty("CLIPS_LM_CACHE_DIR") : option;
  if (dir == "off") return "";
  if (dir.empty()) {
    if (std::string x = env_or_empty("XDG_CACHE_HOME"); !x.empty()) dir = x + "/clips";
    else if (std::string h = env_or_empty("HOME"); !h.empty()) dir = h + "/.cache/clips";
  }
  return dir;
}

// Size and modification time of a file, as text ("" if it cannot be read).
std::string file_stamp(const fs::path& p) {
  std::error_code ec;
  const auto size = fs::file_size(p, ec);
  if (ec) return "";
  const auto mtime = fs::last_write_time(p, ec);
  if (ec) return "";
  return p.string() + ":" + std::to_string(size) + ":" + std::to_string(mtime.time_since_epoch().count());
}

// The regular files of a directory; none if it cannot be read (no throwing:
// the cache is an optimisation and must never fail a run).
std::vector<fs::path> regular_files(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec)) out.push_back(it->path());
  return out;
}

// What a trained model depends on besides its training pairs: the training
// code's version and the WordNet database (its files' sizes and times).
std::string cache_identity() {
  std::string id = "training " + std::to_string(kEmbeddedTrainingVersion);
  std::string wn_dir = env_or_empty("WNSEARCHDIR");
  if (wn_dir.empty()) wn_dir = "/usr/share/wordnet";
  std::vector<std::string> stamps;
  for (const fs::path& f : regular_files(wn_dir)) stamps.push_back(file_stamp(f));
  std::sort(stamps.begin(), stamps.end());
  for (const auto& x : stamps) id += "|" + x;
  return id;
}

// The noun senses in a cache key: a model trained with other senses differs.
std::string senses_text(const NounSenses& senses) {
  std::string out;
  for (const auto& [type, sense] : senses) out += "|" + type + "#" + std::to_string(sense);
  return out;
}

std::string cache_key(const std::string& identity, const std::vector<TrainingPair>& pairs, int iterations) {
  std::ostringstream o;
  o << "clips-embedded-lm/1\n" << identity << "\n" << iterations << "\n";
  o.precision(17);
  for (const auto& p : pairs) o << p.command << '\t' << p.utterance << '\t' << p.weight << '\n';
  const std::string text = o.str();
  // Two differently seeded 64-bit hashes: a collision would load the wrong model.
  char hex[33];
  std::snprintf(hex, sizeof(hex), "%016llx%016llx", static_cast<unsigned long long>(util::fnv1a64(text)),
                static_cast<unsigned long long>(util::fnv1a64(text, 0x84222325cbf29ce4ull ^ text.size())));
  return hex;
}

std::shared_ptr<AlignmentModel> load_cached(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return nullptr;
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return AlignmentModel::load(bytes);
  } catch (const LmError&) {
    return nullptr;  // damaged or from another format: train again and overwrite
  }
}

// Best effort: a cache that cannot be written only costs the next run a training.
void store_cached(const fs::path& dir, const fs::path& file, const AlignmentModel& model) {
  static std::atomic<unsigned> counter{0};
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return;
  // Write then rename, so a concurrent reader sees a whole file or none.
  const fs::path tmp = file.string() + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  {
    std::ofstream out(tmp, std::ios::binary);
    const std::string bytes = model.save();
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      out.close();
      fs::remove(tmp, ec);
      return;
    }
  }
  fs::rename(tmp, file, ec);
  if (ec) {
    fs::remove(tmp, ec);
    return;
  }
  // Keep the directory bounded: the newest 64 snapshots (about 0.5 MB each).
  std::vector<std::pair<fs::file_time_type, fs::path>> entries;
  for (const fs::path& f : regular_files(dir)) {
    const std::string name = f.filename().string();
    if (name.rfind("embedded-", 0) == 0 && f.extension() == ".bin") entries.emplace_back(fs::last_write_time(f, ec), f);
  }
  if (entries.size() <= 64) return;
  std::sort(entries.begin(), entries.end());
  for (size_t i = 0; i + 64 < entries.size(); ++i) fs::remove(entries[i].second, ec);
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
  for (const TrainingPair& p : options_.extra_corpus) {
    parse_command_frame(p.command, p.origin);  // fail now, naming the pair
    corpus_.push_back(p);
  }
  cache_dir_ = resolve_cache_dir(options_.cache_dir);
  if (!cache_dir_.empty()) cache_identity_ = cache_identity();
  if (cache_identity_.empty()) cache_dir_.clear();
}

size_t EmbeddedLanguageModel::cache_hits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return cache_hits_;
}

EmbeddedLanguageModel::~EmbeddedLanguageModel() = default;

struct EmbeddedLanguageModel::BlockSlot {
  std::once_flag once;
  std::shared_ptr<BlockState> state;  // set once `once` has run
};

size_t EmbeddedLanguageModel::trained_blocks() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return trained_;
}

std::shared_ptr<EmbeddedLanguageModel::BlockState> EmbeddedLanguageModel::block_state(const std::string& block) {
  std::shared_ptr<BlockSlot> slot;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto& s = blocks_[block];
    if (!s) s = std::make_shared<BlockSlot>();
    slot = s;
  }
  // A training that throws leaves the flag unset: the next caller tries again.
  std::call_once(slot->once, [&] { slot->state = train_block(block); });
  return slot->state;
}

std::shared_ptr<EmbeddedLanguageModel::BlockState> EmbeddedLanguageModel::train_block(const std::string& block) {
  std::vector<TrainingPair> pairs = corpus_;
  int index = 0;
  for (const auto& [cmd, utt] : parse_fewshot_block(block)) {
    ++index;
    pairs.push_back(TrainingPair{cmd, utt, options_.fewshot_weight, "prompt example " + std::to_string(index)});
  }
  auto state = std::make_shared<BlockState>();
  if (!cache_dir_.empty()) {
    const fs::path file =
        fs::path(cache_dir_) / ("embedded-" + cache_key(cache_identity_ + senses_text(options_.noun_senses), pairs,
                                                        options_.em_iterations) + ".bin");
    state->model = load_cached(file);
    if (state->model) {
      std::lock_guard<std::mutex> lock(mutex_);
      ++cache_hits_;
    } else {
      state->model = AlignmentModel::train(pairs, options_.em_iterations, options_.noun_senses);
      store_cached(cache_dir_, file, *state->model);
    }
  } else {
    state->model = AlignmentModel::train(pairs, options_.em_iterations, options_.noun_senses);
  }
  state->model->set_function_words(options_.function_words);
  state->model->set_noun_senses(options_.noun_senses);
  std::lock_guard<std::mutex> lock(mutex_);
  ++trained_;
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
  // Blocks the batch needs that are not trained yet train side by side (each
  // on its own thread; a model does not depend on which thread trains it).
  std::vector<std::string> untrained;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const ScoreRequest& r : batch) {
      std::string block = split_prompt(r.prompt).first;
      if (!blocks_.count(block) && std::find(untrained.begin(), untrained.end(), block) == untrained.end())
        untrained.push_back(std::move(block));
    }
  }
  if (untrained.size() > 1) {
    std::vector<std::future<void>> training;
    for (size_t i = 1; i < untrained.size(); ++i)
      training.push_back(std::async(std::launch::async, [this, &untrained, i] { block_state(untrained[i]); }));
    block_state(untrained[0]);
    for (auto& t : training) t.get();  // rethrows a training's error
  }
  std::vector<double> out;
  out.reserve(batch.size());
  for (const ScoreRequest& r : batch) out.push_back(score_one(r.prompt, r.continuation));
  return out;
}

}  // namespace clips::lm
