#include "app/bench_shard_test.hpp"

namespace clips::eval {
namespace bench_shard_test {
TEST(BenchShardCli, MergeTakesNoBenchOptions) {
  testing::TempDir tmp("bench-merge-opts");
  // Refused before any folder is read.
  const auto r = run(clips_binary() + " bench --seed 3 merge --out " + tmp.str() + "/out " + tmp.str() + "/none");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--seed is an option of `clips bench`, not of `clips bench merge`")) << r.out;
}

}  // namespace bench_shard_test

}  // namespace clips::eval
