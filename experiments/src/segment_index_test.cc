// The index shrinks its cells where segments crowd (a world of chair legs, 48 facets each); the
// answers must stay those of a brute-force scan. The sparse cases are in metrics_test.cc.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cogmap/experiments/segment_index.h"

namespace cogmap::experiments {
namespace {

using mapper::Point2;
using mapper::Segment;

// 300 circles of 2 cm radius as 48-gons in a 3 x 3 m square: 14 400 facets, about 1 600 per
// square metre, where a 0.5 m cell would hold ~400 of them.
std::vector<Segment> chair_legs() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> place(0.0, 3.0);
  std::vector<Segment> segs;
  for (int c = 0; c < 300; ++c) {
    const Point2 centre(place(rng), place(rng));
    for (int k = 0; k < 48; ++k) {
      const double a0 = 2.0 * std::numbers::pi * k / 48, a1 = 2.0 * std::numbers::pi * (k + 1) / 48;
      segs.push_back({centre + 0.02 * Point2(std::cos(a0), std::sin(a0)),
                      centre + 0.02 * Point2(std::cos(a1), std::sin(a1))});
    }
  }
  return segs;
}

TEST(SegmentIndexCrowded, EveryQueryMatchesBruteForce) {
  const std::vector<Segment> segs = chair_legs();
  const SegmentIndex index(segs, 0.5);
  // sqrt(8 × 3.54² / 14 400) = 0.083 m (the legs' box, 3.04 m, plus the 0.5 m cell asked
  // for): about eight facets a cell.
  EXPECT_NEAR(index.cell_m(), 0.083, 0.001);
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-0.5, 3.5);
  int blocked = 0, clear = 0, near = 0;
  for (int k = 0; k < 300; ++k) {
    const Point2 p(u(rng), u(rng)), q(u(rng), u(rng));
    double nearest = INFINITY;
    bool crossed = false;
    for (const Segment& s : segs) {
      nearest = std::min(nearest, mapper::distance_to_segment_m(p, s));
      crossed = crossed || segments_intersect(p, q, s.a, s.b);
    }
    ASSERT_DOUBLE_EQ(index.nearest_distance_m(p), nearest) << k;
    ASSERT_EQ(index.any_within_m(p, 0.05), nearest <= 0.05) << k;
    ASSERT_EQ(index.nearest_point_within(p, 0.05).has_value(), nearest <= 0.05) << k;
    ASSERT_EQ(index.blocked(p, q, SegmentIndex::kNone), crossed) << k;
    (crossed ? blocked : clear)++;
    near += nearest <= 0.05;
    // A short sight line, which mostly threads between the legs.
    const Point2 r = p + 0.2 * (q - p).normalized();
    bool short_crossed = false;
    for (const Segment& s : segs)
      short_crossed = short_crossed || segments_intersect(p, r, s.a, s.b);
    ASSERT_EQ(index.blocked(p, r, SegmentIndex::kNone), short_crossed) << k;
    clear += !short_crossed;
  }
  // Both answers were exercised.
  EXPECT_GT(blocked, 100);
  EXPECT_GT(clear, 100);
  EXPECT_GT(near, 10);
}

TEST(SegmentIndexCrowded, AnOrdinaryBuildingKeepsItsCells) {
  // A 10 x 6 m two-room block with a desk: far fewer segments than 0.5 m cells.
  const std::vector<Segment> walls{{{0, 0}, {10, 0}}, {{10, 0}, {10, 6}}, {{10, 6}, {0, 6}},
                                   {{0, 6}, {0, 0}},  {{5, 0}, {5, 2.5}}, {{5, 3.5}, {5, 6}},
                                   {{1, 5}, {3, 5}},  {{3, 5}, {3, 5.8}}, {{3, 5.8}, {1, 5.8}}};
  EXPECT_DOUBLE_EQ(SegmentIndex(walls, 0.5).cell_m(), 0.5);
}

}  // namespace
}  // namespace cogmap::experiments
