#pragma once
// CachedLanguageModel: memoises another LanguageModel by (prompt, continuation).
//
// Inference scores the same (prompt, utterance) pair many times (the same lifted
// command recurs across goal hypotheses and time steps); each unique pair is
// sent to the wrapped model once per run. Within one score() call duplicates
// are also collapsed, and only the misses are forwarded, as one batch, in
// first-occurrence order. Thread-safe: the table is guarded by a mutex that is
// NOT held while the wrapped model works, so two threads may occasionally score
// the same new pair twice (harmless: models are deterministic; counted as misses).
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "lm/language_model.hpp"

namespace clips::lm {

class CachedLanguageModel : public LanguageModel {
 public:
  // Non-owning: `inner` must outlive this object.
  explicit CachedLanguageModel(LanguageModel& inner);
  explicit CachedLanguageModel(std::shared_ptr<LanguageModel> inner);

  std::string name() const override;  // "cached(<inner name>)"
  std::vector<double> score(const std::vector<ScoreRequest>& batch) override;

  uint64_t hits() const { return hits_.load(); }
  uint64_t misses() const { return misses_.load(); }
  size_t size() const;
  void clear();

 private:
  std::shared_ptr<LanguageModel> owned_;
  LanguageModel& inner_;
  mutable std::mutex mutex_;
  // Key: prompt + '\0' + continuation (neither contains NUL in practice; the
  // prompt length is also prefixed so the split is unambiguous).
  std::unordered_map<std::string, double> table_;
  std::atomic<uint64_t> hits_{0};
  std::atomic<uint64_t> misses_{0};
};

}  // namespace clips::lm
