// CachedLanguageModel: each unique (prompt, continuation) reaches the inner model once.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "lm/cached_model.hpp"

namespace clips::lm {
namespace {

class CountingModel : public LanguageModel {
 public:
  std::string name() const override { return "counting"; }
  std::vector<double> score(const std::vector<ScoreRequest>& batch) override {
    calls += 1;
    scored += static_cast<int>(batch.size());
    std::vector<double> out;
    for (const auto& r : batch) out.push_back(-static_cast<double>(r.prompt.size() * 100 + r.continuation.size()));
    return out;
  }
  std::atomic<int> calls{0};
  std::atomic<int> scored{0};
};

TEST(CachedModel, ScoresEachUniquePairOnce) {
  CountingModel inner;
  CachedLanguageModel cached(inner);
  const std::vector<ScoreRequest> batch = {{"p1", " a\n"}, {"p2", " a\n"}, {"p1", " a\n"}, {"p1", " bb\n"}};
  auto first = cached.score(batch);
  EXPECT_EQ(inner.scored.load(), 3);
  EXPECT_EQ(first[0], first[2]);
  EXPECT_EQ(first[1], -203.0);
  auto second = cached.score(batch);
  EXPECT_EQ(first, second);
  EXPECT_EQ(inner.scored.load(), 3);
  EXPECT_EQ(inner.calls.load(), 1);
  EXPECT_EQ(cached.misses(), 3u);
  EXPECT_EQ(cached.hits(), 5u);  // one duplicate in the first batch, four in the second
  EXPECT_EQ(cached.size(), 3u);
  EXPECT_EQ(cached.name(), "cached(counting)");
}

TEST(CachedModel, KeyDistinguishesPromptContinuationBoundary) {
  CountingModel inner;
  CachedLanguageModel cached(inner);
  auto s = cached.score({{"ab", "c"}, {"a", "bc"}});
  EXPECT_NE(s[0], s[1]);
  EXPECT_EQ(inner.scored.load(), 2);
}

TEST(CachedModel, OwnsSharedInnerAndIsThreadSafe) {
  auto inner = std::make_shared<CountingModel>();
  CachedLanguageModel cached(inner);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&cached] {
      for (int i = 0; i < 200; ++i) {
        cached.score({{"p" + std::to_string(i % 50), " u\n"}});
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(cached.size(), 50u);
  EXPECT_EQ(cached.hits() + cached.misses(), 800u);
  EXPECT_GE(inner->scored.load(), 50);
  cached.clear();
  EXPECT_EQ(cached.size(), 0u);
}

TEST(CachedModel, EmptyBatch) {
  CountingModel inner;
  CachedLanguageModel cached(inner);
  EXPECT_TRUE(cached.score({}).empty());
  EXPECT_EQ(inner.calls.load(), 0);
}

}  // namespace
}  // namespace clips::lm
