// What every updater shares: kind names, the factory, reading rejection, growth, grid_bytes.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cogmap/mapper/grid/grid_updater.h"
#include "grid/grid_test_support.h"

namespace cogmap::mapper {
namespace {

using testing::cells_differing;
using testing::echo;
using testing::single_forward_sonar;

constexpr GridKind kAllKinds[] = {GridKind::kHimm, GridKind::kMhimm, GridKind::kBayes,
                                  GridKind::kDempsterShafer};

TEST(GridKind, NamesRoundTrip) {
  for (GridKind kind : kAllKinds) EXPECT_EQ(parse_grid_kind(to_string(kind)), kind);
  EXPECT_EQ(to_string(GridKind::kDempsterShafer), "dempster_shafer");
  EXPECT_EQ(parse_grid_kind("mhimm"), GridKind::kMhimm);
  EXPECT_FALSE(parse_grid_kind("MHIMM").has_value());
  EXPECT_FALSE(parse_grid_kind("").has_value());
  EXPECT_FALSE(parse_grid_kind("dempster-shafer").has_value());
}

TEST(GridUpdaterFactory, BuildsEveryKind) {
  for (GridKind kind : kAllKinds) {
    auto u = make_grid_updater(kind, {}, p2at_geometry());
    ASSERT_NE(u, nullptr);
    EXPECT_EQ(u->kind(), kind);
    EXPECT_EQ(u->geometry().width(), 120);  // 12 m at 10 cm
    EXPECT_EQ(u->rejected().total(), 0u);
  }
}

TEST(GridUpdater, RejectedReadingsAreCountedByReasonAndNeverWritten) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Pose2 pose{0.3, -0.2, 0.4};
  for (GridKind kind : kAllKinds) {
    auto u = make_grid_updater(kind, {}, p2at_geometry());
    u->mark_robot(pose);
    for (int i = 0; i < 16; ++i) ASSERT_TRUE(u->integrate(pose, echo(i, 0.4 + 0.1 * i)));
    const HistogramGrid before = u->histogram();
    EXPECT_FALSE(u->integrate(pose, echo(3, nan)));
    EXPECT_FALSE(u->integrate(pose, echo(3, inf)));
    EXPECT_FALSE(u->integrate(pose, echo(3, -inf)));
    EXPECT_FALSE(u->integrate(pose, echo(3, 0.0)));
    EXPECT_FALSE(u->integrate(pose, echo(3, -1.0)));
    EXPECT_FALSE(u->integrate(pose, {3, -1.0, false, 0.0}));
    EXPECT_FALSE(u->integrate(pose, echo(3, 5.001)));
    EXPECT_FALSE(u->integrate(pose, echo(16, 1.0)));
    EXPECT_FALSE(u->integrate(pose, echo(-1, 1.0)));
    const RejectedReadings& r = u->rejected();
    EXPECT_EQ(r.not_finite, 3u) << to_string(kind);
    EXPECT_EQ(r.non_positive, 3u);
    EXPECT_EQ(r.beyond_max, 1u);
    EXPECT_EQ(r.unknown_sonar, 2u);
    EXPECT_EQ(r.total(), 9u);
    const HistogramGrid after = u->histogram();
    ASSERT_EQ(after.geometry().cell_count(), before.geometry().cell_count());
    EXPECT_EQ(cells_differing(after, before), 0u) << to_string(kind);
    // A reading exactly at max range is valid.
    EXPECT_TRUE(u->integrate(pose, echo(3, 5.0)));
  }
}

TEST(GridUpdater, ResetStartsAFreshRoomAroundTheCentre) {
  for (GridKind kind : kAllKinds) {
    auto u = make_grid_updater(kind, {}, single_forward_sonar());
    ASSERT_TRUE(u->integrate({0.05, 0.05, 0.0}, echo(0, 1.0)));
    u->reset({10.0, -4.0});
    EXPECT_NEAR(u->geometry().origin_x_m(), 4.0, 1e-12);
    EXPECT_NEAR(u->geometry().origin_y_m(), -10.0, 1e-12);
    EXPECT_EQ(cells_differing(u->histogram(), HistogramGrid(u->geometry(), 0.0f)), 0u);
  }
}

TEST(GridUpdater, GrowsSoAFarReadingLandsInTheRightWorldCell) {
  for (GridKind kind : kAllKinds) {
    auto u = make_grid_updater(kind, {}, single_forward_sonar());
    u->reset({0.0, 0.0});
    ASSERT_TRUE(u->integrate({0.05, 0.05, 0.0}, echo(0, 1.0)));  // near hit at (1.05, 0.05)
    const float near_value = u->histogram_at(u->geometry().cell_of({1.05, 0.05}));
    EXPECT_GT(near_value, 0.0f) << to_string(kind);
    const std::size_t bytes_before = u->grid_bytes();
    // Far outside the 12 m room, on both sides.
    const Pose2 far{-20.05, 31.05, std::numbers::pi};  // looks towards -x
    ASSERT_TRUE(u->integrate(far, echo(0, 1.0)));      // hit at (-21.05, 31.05)
    const GridGeometry& g = u->geometry();
    const CellIndex hit = g.cell_of({-21.05, 31.05});
    ASSERT_TRUE(g.contains(hit));
    EXPECT_LT((g.center_of(hit) - Point2(-21.05, 31.05)).norm(), 0.0708);  // inside the cell
    EXPECT_GT(u->histogram_at(hit), 0.0f) << to_string(kind);
    // Cells behind the hit along the beam are seen empty (HIMM floors at 0, so skip it).
    if (kind != GridKind::kHimm) {
      EXPECT_LT(u->histogram_at(g.cell_of({-20.55, 31.05})), 0.0f) << to_string(kind);
    }
    // The first reading kept its world position through the growth.
    EXPECT_EQ(u->histogram_at(g.cell_of({1.05, 0.05})), near_value) << to_string(kind);
    EXPECT_GT(u->grid_bytes(), bytes_before);
    EXPECT_EQ(u->histogram().geometry().cell_count(), g.cell_count());
  }
}

TEST(GridUpdater, GridBytesCountEveryArray) {
  const std::size_t cells = 120 * 120;
  EXPECT_EQ(make_grid_updater(GridKind::kMhimm, {}, p2at_geometry())->grid_bytes(), cells * 4);
  EXPECT_EQ(make_grid_updater(GridKind::kHimm, {}, p2at_geometry())->grid_bytes(), cells * 5);
  EXPECT_EQ(make_grid_updater(GridKind::kBayes, {}, p2at_geometry())->grid_bytes(), cells * 5);
  EXPECT_EQ(make_grid_updater(GridKind::kDempsterShafer, {}, p2at_geometry())->grid_bytes(),
            cells * 13);
}

}  // namespace
}  // namespace cogmap::mapper
