#include "lm/cached_model.hpp"

namespace clips::lm {
namespace {

std::string make_key(const ScoreRequest& r) {
  std::string k = std::to_string(r.prompt.size());
  k.push_back(':');
  k.reserve(k.size() + r.prompt.size() + r.continuation.size() + 1);
  k += r.prompt;
  k.push_back('\0');
  k += r.continuation;
  return k;
}

}  // namespace

CachedLanguageModel::CachedLanguageModel(LanguageModel& inner) : inner_(inner) {}

CachedLanguageModel::CachedLanguageModel(std::shared_ptr<LanguageModel> inner)
    : owned_(std::move(inner)), inner_(*owned_) {
  if (!owned_) throw LmError("cached LM: null inner model");
}

std::string CachedLanguageModel::name() const { return "cached(" + inner_.name() + ")"; }

size_t CachedLanguageModel::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return table_.size();
}

void CachedLanguageModel::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  table_.clear();
}

std::vector<double> CachedLanguageModel::score(const std::vector<ScoreRequest>& batch) {
  std::vector<double> out(batch.size(), 0.0);
  std::vector<std::string> keys;
  keys.reserve(batch.size());
  for (const ScoreRequest& r : batch) keys.push_back(make_key(r));

  // Look everything up; collect the distinct misses.
  std::vector<ScoreRequest> todo;
  std::unordered_map<std::string, size_t> todo_index;  // key -> index in todo
  std::vector<long> slot(batch.size(), -1);            // index into todo, or -1 if hit
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t i = 0; i < batch.size(); ++i) {
      auto it = table_.find(keys[i]);
      if (it != table_.end()) {
        out[i] = it->second;
        ++hits_;
        continue;
      }
      auto [t, inserted] = todo_index.emplace(keys[i], todo.size());
      if (inserted) {
        todo.push_back(batch[i]);
        ++misses_;
      } else {
        ++hits_;  // a duplicate inside this batch is scored once
      }
      slot[i] = static_cast<long>(t->second);
    }
  }
  if (todo.empty()) return out;

  std::vector<double> fresh = inner_.score(todo);
  if (fresh.size() != todo.size()) {
    throw LmError("cached LM: inner model " + inner_.name() + " returned " + std::to_string(fresh.size()) +
                  " scores for " + std::to_string(todo.size()) + " requests");
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [key, idx] : todo_index) table_.emplace(key, fresh[idx]);
  }
  for (size_t i = 0; i < batch.size(); ++i) {
    if (slot[i] >= 0) out[i] = fresh[static_cast<size_t>(slot[i])];
  }
  return out;
}

}  // namespace clips::lm
