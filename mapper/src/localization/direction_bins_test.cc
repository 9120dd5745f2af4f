#include "cogmap/mapper/localization/direction_bins.h"
#include "cogmap/test_support/angles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace cogmap::mapper {
namespace {

TEST(DirectionBins, ABinHoldsItsMembersMeanLengthSpreadAndSquaredLengths) {
  // 1° bins tile [−45°, 45°) from −45°, so 10.2° and 10.6° share the bin [10°, 11°).
  const std::vector<LineDirection> in{{10.2 * kDeg, 1.0}, {10.6 * kDeg, 3.0}};
  const BinnedDirections b = bin_directions(in, 1.0 * kDeg);
  ASSERT_EQ(b.directions.size(), 1u);
  EXPECT_NEAR(b.directions[0].angle_rad, 10.5 * kDeg, 1e-12);  // (10.2 + 3·10.6) / 4
  EXPECT_DOUBLE_EQ(b.directions[0].length_m, 4.0);
  // (1·0.3² + 3·0.1²) / 4 = 0.03 deg².
  EXPECT_NEAR(b.spread_rad2[0], 0.03 * kDeg * kDeg, 1e-15);
  EXPECT_DOUBLE_EQ(b.length_sq[0], 10.0);  // 1² + 3²
}

TEST(DirectionBins, FoldedDirectionsShareABinAndBinsComeInAngleOrder) {
  // 100.4° is 10.4° modulo 90°; −44.9° and 44.9° lie in the first and the last bin.
  const std::vector<LineDirection> in{
      {44.9 * kDeg, 1.0}, {100.4 * kDeg, 2.0}, {10.2 * kDeg, 2.0}, {-44.9 * kDeg, 1.0}};
  const BinnedDirections b = bin_directions(in, 1.0 * kDeg);
  ASSERT_EQ(b.directions.size(), 3u);
  EXPECT_NEAR(b.directions[0].angle_rad, -44.9 * kDeg, 1e-12);
  EXPECT_NEAR(b.directions[1].angle_rad, 10.3 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(b.directions[1].length_m, 4.0);
  EXPECT_NEAR(b.spread_rad2[1], 0.01 * kDeg * kDeg, 1e-15);
  EXPECT_NEAR(b.directions[2].angle_rad, 44.9 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(b.spread_rad2[0], 0.0);  // one member: no spread
}

TEST(DirectionBins, DirectionsOnBothSidesOfABinEdgeStayApart) {
  const std::vector<LineDirection> in{{9.99 * kDeg, 1.0}, {10.01 * kDeg, 1.0}};
  EXPECT_EQ(bin_directions(in, 1.0 * kDeg).directions.size(), 2u);
  EXPECT_EQ(bin_directions(in, 2.0 * kDeg).directions.size(), 1u);  // [9°, 11°)
}

TEST(DirectionBins, ZeroLengthAndNonFiniteDirectionsAreLeftOut) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<LineDirection> in{{5.0 * kDeg, 0.0}, {nan, 1.0}, {5.2 * kDeg, nan}};
  EXPECT_TRUE(bin_directions(in, 0.25 * kDeg).directions.empty());
}

TEST(DirectionBins, NoBinWidthKeepsEveryDirection) {
  const std::vector<LineDirection> in{{10.2 * kDeg, 1.0}, {10.6 * kDeg, 3.0}};
  for (const double width : {0.0, -1.0, std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::denorm_min(), 1e-12}) {
    const BinnedDirections b = bin_directions(in, width);
    ASSERT_EQ(b.directions.size(), 2u);
    EXPECT_EQ(b.directions[1].angle_rad, 10.6 * kDeg);
    EXPECT_EQ(b.spread_rad2, (std::vector<double>{0.0, 0.0}));
    EXPECT_EQ(b.length_sq, (std::vector<double>{1.0, 9.0}));
  }
}

TEST(DirectionBins, ManyDirectionsNeverMakeMoreEntriesThanBins) {
  std::vector<LineDirection> in;
  for (int i = 0; i < 5000; ++i) in.push_back({(-45.0 + 0.018 * i) * kDeg, 1.0});
  EXPECT_EQ(bin_directions(in, 0.25 * kDeg).directions.size(), 360u);
}

}  // namespace
}  // namespace cogmap::mapper
