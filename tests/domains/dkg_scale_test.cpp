#include "domains/dkg_scale_test.hpp"

namespace clips::domains::dkg {
namespace dkg_scale_test {
TEST(ObjMask, BitsAboveSixtyFour) {
  static_assert(kObjMaskBits == 128);
  const ObjMask m = mask_bit(0) | mask_bit(63) | mask_bit(64) | mask_bit(100) | mask_bit(127);
  EXPECT_TRUE(mask_has(m, 0) && mask_has(m, 63) && mask_has(m, 64) && mask_has(m, 100) && mask_has(m, 127));
  EXPECT_FALSE(mask_has(m, 1) || mask_has(m, 62) || mask_has(m, 65) || mask_has(m, 126));
  EXPECT_EQ(mask_popcount(m), 5);
  EXPECT_EQ(mask_ctz(m), 0);
  EXPECT_EQ(mask_ctz(mask_bit(64)), 64);
  EXPECT_EQ(mask_ctz(mask_bit(127)), 127);
  EXPECT_EQ(mask_ctz(mask_bit(64) | mask_bit(90)), 64);
  std::vector<int> seen;
  mask_for_each(m, [&](int i) { seen.push_back(i); });
  EXPECT_EQ(seen, (std::vector<int>{0, 63, 64, 100, 127}));
  // The low word alone is the old 64-bit mask.
  EXPECT_EQ(static_cast<uint64_t>(mask_bit(5) | mask_bit(70)), uint64_t{1} << 5);
  EXPECT_EQ(mask_popcount(~ObjMask{0}), 128);
}

}  // namespace dkg_scale_test

}  // namespace clips::domains::dkg
