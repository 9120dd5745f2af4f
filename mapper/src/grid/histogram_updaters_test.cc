// HIMM (Fig. A.2) and MHIMM (Fig. A.3) on scripted readings with hand-computed cell values.
// Default options: 10 cm cells, 12 m initial extent centred on (0, 0) -> origin (-6, -6), so a
// robot at (0.05, 0.05) sits in cell (60, 60).

#include <gtest/gtest.h>

#include <vector>

#include "cogmap/mapper/grid/grid_updater.h"
#include "grid/grid_test_support.h"

namespace cogmap::mapper {
namespace {

using testing::cells_differing;
using testing::echo;
using testing::single_forward_sonar;

using testing::kRobot;
constexpr CellIndex kRobotCell{60, 60};

/// The increments of thesis Figs. A.2-A.3 (+1.5 on the cell, +1.5 on each of the 3x3), a 2 m
/// window and Fig. A.3's clearing of no-echo beams to the window edge, which the exact values
/// below follow; the defaults are checked separately.
GridOptions fig_a2_options() {
  GridOptions options;
  options.window_m = 2.0;
  options.no_echo_clear_m = -1.0;
  options.hit_increment = 1.5;
  options.neighbour_increment = 1.5;
  return options;
}

std::unique_ptr<GridUpdater> make(GridKind kind, const RobotGeometry& robot,
                                  const GridOptions& options = fig_a2_options()) {
  auto u = make_grid_updater(kind, options, robot);
  u->reset({0.0, 0.0});
  return u;
}

// Sonar 3 of the P2-AT at 1.0 m from (0.05, 0.05, 0): hit (1.2798, 0.2506) -> cell (72, 62);
// Bresenham (60, 60) -> (72, 62) as listed.
const std::vector<CellIndex> kSonar3Line{{60, 60}, {61, 60}, {62, 60}, {63, 61},
                                         {64, 61}, {65, 61}, {66, 61}, {67, 61},
                                         {68, 61}, {69, 62}, {70, 62}, {71, 62}};
constexpr CellIndex kSonar3Hit{72, 62};

TEST(Himm, OneReadingOfSonar3) {
  auto u = make(GridKind::kHimm, p2at_geometry());
  ASSERT_EQ(u->geometry().cell_of(kRobot.translation()), kRobotCell);
  ASSERT_TRUE(u->integrate(kRobot, echo(3, 1.0)));
  EXPECT_FLOAT_EQ(u->histogram_at(kSonar3Hit), 3.0f);  // 1.5 + 1.5 from the 3x3 loop
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const CellIndex c{kSonar3Hit.x + dx, kSonar3Hit.y + dy};
      if (dx == 0 && dy == 0) continue;
      // (71, 62) lies on the beam: +1.5, then -1 by the line decrement.
      EXPECT_FLOAT_EQ(u->histogram_at(c), (c == CellIndex{71, 62}) ? 0.5f : 1.5f) << c.x << c.y;
    }
  }
  for (const CellIndex& c : kSonar3Line) {
    if (c == CellIndex{71, 62}) continue;
    EXPECT_FLOAT_EQ(u->histogram_at(c), 0.0f);  // HIMM floors at 0
  }
  // Exactly the 9 cells of the block changed.
  EXPECT_EQ(cells_differing(u->histogram(), HistogramGrid(u->geometry(), 0.0f)), 9u);
}

TEST(Mhimm, OneReadingOfSonar3) {
  auto u = make(GridKind::kMhimm, p2at_geometry());
  ASSERT_TRUE(u->integrate(kRobot, echo(3, 1.0)));
  EXPECT_FLOAT_EQ(u->histogram_at(kSonar3Hit), 3.0f);
  EXPECT_FLOAT_EQ(u->histogram_at({71, 62}), 0.5f);
  EXPECT_FLOAT_EQ(u->histogram_at({73, 63}), 1.5f);
  EXPECT_FLOAT_EQ(u->histogram_at({71, 61}), 1.5f);
  for (const CellIndex& c : kSonar3Line) {
    if (c == CellIndex{71, 62}) continue;
    EXPECT_FLOAT_EQ(u->histogram_at(c), -1.0f) << c.x << " " << c.y;  // MHIMM may go below 0
  }
  EXPECT_EQ(cells_differing(u->histogram(), HistogramGrid(u->geometry(), 0.0f)),
            9u + kSonar3Line.size() - 1);
}

TEST(Mhimm, DefaultIncrementsFollowSection223) {
  auto u = make(GridKind::kMhimm, p2at_geometry(), GridOptions{});
  ASSERT_TRUE(u->integrate(kRobot, echo(3, 1.0)));
  EXPECT_FLOAT_EQ(u->histogram_at(kSonar3Hit), 3.0f);  // 2.5 + 0.5
  EXPECT_FLOAT_EQ(u->histogram_at({73, 63}), 0.5f);    // neighbour off the beam
  EXPECT_FLOAT_EQ(u->histogram_at({71, 62}), -0.5f);   // neighbour on the beam: 0.5 - 1
  EXPECT_FLOAT_EQ(u->histogram_at({66, 61}), -1.0f);   // plain beam cell
}

TEST(Himm, LineDecrementLowersEarlierHits) {
  auto u = make(GridKind::kHimm, single_forward_sonar());
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 0.5)));  // hit (0.55, 0.05) -> (65, 60)
  EXPECT_FLOAT_EQ(u->histogram_at({65, 60}), 3.0f);
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));  // hit (70, 60); beam passes (65, 60)
  EXPECT_FLOAT_EQ(u->histogram_at({65, 60}), 2.0f);
  EXPECT_FLOAT_EQ(u->histogram_at({64, 60}), 0.0f);  // 1.5 - 1 (reading 1), - 1 floored
  EXPECT_FLOAT_EQ(u->histogram_at({64, 61}), 1.5f);  // neighbour off both beams
  EXPECT_FLOAT_EQ(u->histogram_at({66, 60}), 0.5f);  // 1.5 (reading 1) - 1 (reading 2)
  EXPECT_FLOAT_EQ(u->histogram_at({65, 61}), 1.5f);  // off the beam, untouched by reading 2
  EXPECT_FLOAT_EQ(u->histogram_at({70, 60}), 3.0f);
  EXPECT_FLOAT_EQ(u->histogram_at({69, 60}), 0.5f);
}

TEST(HistogramUpdaters, RepeatedHitsCapAt15) {
  for (GridKind kind : {GridKind::kHimm, GridKind::kMhimm}) {
    auto u = make(kind, single_forward_sonar());
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));
    EXPECT_FLOAT_EQ(u->histogram_at({70, 60}), 15.0f);  // 3 per reading, capped
    EXPECT_FLOAT_EQ(u->histogram_at({70, 61}), 15.0f);  // 1.5 x 10
    EXPECT_FLOAT_EQ(u->histogram_at({71, 59}), 15.0f);
    EXPECT_FLOAT_EQ(u->histogram_at({69, 60}), 5.0f);  // (+1.5 - 1) x 10
  }
}

TEST(HistogramUpdaters, DecrementsFloorAt0ForHimmAndMinus3ForMhimm) {
  for (GridKind kind : {GridKind::kHimm, GridKind::kMhimm}) {
    auto u = make(kind, single_forward_sonar());
    for (int i = 0; i < 6; ++i) ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.5)));
    const float floor = kind == GridKind::kHimm ? 0.0f : -3.0f;
    for (int x = 60; x <= 73; ++x) EXPECT_FLOAT_EQ(u->histogram_at({x, 60}), floor) << x;
    EXPECT_FLOAT_EQ(u->histogram_at({74, 60}), 3.0f);  // (+0.5 per reading) x 6
    EXPECT_FLOAT_EQ(u->histogram_at({75, 60}), 15.0f);
  }
}

TEST(Mhimm, PathCellStaysMinus100) {
  auto u = make(GridKind::kMhimm, single_forward_sonar());
  const Pose2 ahead{0.55, 0.05, 0.0};  // cell (65, 60)
  u->mark_robot(kRobot);
  u->mark_robot(ahead);
  EXPECT_FLOAT_EQ(u->histogram_at(kRobotCell), kRobotPathValue);
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));  // line through (65, 60)
    ASSERT_TRUE(u->integrate(kRobot, echo(0, 0.6)));  // hit (66, 60): (65, 60) a neighbour
    ASSERT_TRUE(u->integrate(kRobot, echo(0, 0.5)));  // hit on (65, 60) itself
    ASSERT_TRUE(u->integrate(ahead, echo(0, 3.0)));   // beyond w, starts at the path cell
  }
  EXPECT_FLOAT_EQ(u->histogram_at(kRobotCell), kRobotPathValue);
  EXPECT_FLOAT_EQ(u->histogram_at({65, 60}), kRobotPathValue);
  EXPECT_FLOAT_EQ(u->histogram().get({65, 60}), kRobotPathValue);
}

TEST(Himm, PathIsReportedButDoesNotProtect) {
  auto u = make(GridKind::kHimm, single_forward_sonar());
  u->mark_robot({0.55, 0.05, 0.0});
  EXPECT_FLOAT_EQ(u->histogram_at({65, 60}), kRobotPathValue);
  EXPECT_FLOAT_EQ(u->histogram().get({65, 60}), kRobotPathValue);
  EXPECT_FLOAT_EQ(u->histogram().get({66, 60}), 0.0f);
}

TEST(Mhimm, ReadingBeyondWindowDecrementsExactlyToTheEdge) {
  auto u = make(GridKind::kMhimm, single_forward_sonar());  // w = 2 m
  u->mark_robot(kRobot);
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 3.0)));  // window edge (2.05, 0.05) -> (80, 60)
  EXPECT_FLOAT_EQ(u->histogram_at(kRobotCell), kRobotPathValue);
  for (int x = 61; x <= 80; ++x) EXPECT_FLOAT_EQ(u->histogram_at({x, 60}), -1.0f) << x;
  EXPECT_FLOAT_EQ(u->histogram_at({81, 60}), 0.0f);
  EXPECT_FLOAT_EQ(u->histogram_at({90, 60}), 0.0f);  // the hit itself is never incremented
  HistogramGrid expected(u->geometry(), 0.0f);
  expected.set(kRobotCell, kRobotPathValue);
  for (int x = 61; x <= 80; ++x) expected.set({x, 60}, -1.0f);
  EXPECT_EQ(cells_differing(u->histogram(), expected), 0u);
}

TEST(Mhimm, NoEchoClearDistanceLimitsWhatANoEchoBeamClears) {
  GridOptions options = fig_a2_options();
  options.no_echo_clear_m = 0.5;  // clears (0.05, 0.05) .. (0.55, 0.05): cells 61..65
  auto u = make(GridKind::kMhimm, single_forward_sonar(), options);
  u->mark_robot(kRobot);
  ASSERT_TRUE(u->integrate(kRobot, {0, 5.0, false, 0.0}));
  for (int x = 61; x <= 65; ++x) EXPECT_FLOAT_EQ(u->histogram_at({x, 60}), -1.0f) << x;
  EXPECT_FLOAT_EQ(u->histogram_at({66, 60}), 0.0f);
  // An echo beyond w still clears to the window edge (thesis Fig. A.3).
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 3.0)));
  EXPECT_FLOAT_EQ(u->histogram_at({80, 60}), -1.0f);
  options.no_echo_clear_m = 0.0;  // a no-echo beam then clears nothing
  auto quiet = make(GridKind::kMhimm, single_forward_sonar(), options);
  const HistogramGrid before = quiet->histogram();
  ASSERT_TRUE(quiet->integrate(kRobot, {0, 5.0, false, 0.0}));
  EXPECT_EQ(cells_differing(quiet->histogram(), before), 0u);
}

TEST(Himm, ReadingBeyondWindowIsAcceptedButIgnored) {
  auto u = make(GridKind::kHimm, single_forward_sonar());
  const HistogramGrid before = u->histogram();
  EXPECT_TRUE(u->integrate(kRobot, echo(0, 3.0)));  // Fig. A.2 has no Else branch
  EXPECT_EQ(cells_differing(u->histogram(), before), 0u);
}

TEST(HistogramUpdaters, NoEchoNeverIncrements) {
  GridOptions wide;
  wide.window_m = 6.0;  // HIMM only integrates beams that end inside w
  for (GridKind kind : {GridKind::kHimm, GridKind::kMhimm}) {
    for (const GridOptions& options : {GridOptions{}, wide}) {
      auto u = make(kind, p2at_geometry(), options);
      for (int i = 0; i < 16; ++i) {
        ASSERT_TRUE(u->integrate({0.3, -0.2, 0.4}, {i, 5.0, false, 0.0}));
        ASSERT_TRUE(u->integrate({0.3, -0.2, 0.4}, {i, 1.0, false, 0.0}));
      }
      const HistogramGrid h = u->histogram();
      float max_value = -1000.0f;
      for (std::size_t c = 0; c < h.geometry().cell_count(); ++c) {
        max_value = std::max(max_value, h.data()[c]);
      }
      EXPECT_EQ(max_value, 0.0f);
    }
  }
}

TEST(Mhimm, NoEchoClearsToTheWindowEdgeInclusive) {
  auto u = make(GridKind::kMhimm, single_forward_sonar());
  ASSERT_TRUE(u->integrate(kRobot, {0, 5.0, false, 0.0}));
  for (int x = 60; x <= 80; ++x) EXPECT_FLOAT_EQ(u->histogram_at({x, 60}), -1.0f) << x;
  EXPECT_FLOAT_EQ(u->histogram_at({81, 60}), 0.0f);
  // A no-echo beam shorter than w clears to its end, end included.
  auto v = make(GridKind::kMhimm, single_forward_sonar());
  ASSERT_TRUE(v->integrate(kRobot, {0, 1.0, false, 0.0}));
  for (int x = 60; x <= 70; ++x) EXPECT_FLOAT_EQ(v->histogram_at({x, 60}), -1.0f) << x;
  EXPECT_FLOAT_EQ(v->histogram_at({71, 60}), 0.0f);
}

}  // namespace
}  // namespace cogmap::mapper
