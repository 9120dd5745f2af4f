// Contact episodes from the true footprint: a P2-AT (0.626 x 0.505 m) driven past a wall at
// known distances, so which frames touch is known by hand.
#include "cogmap/experiments/nav_metrics.h"

#include <gtest/gtest.h>

#include <vector>

#include "cogmap/experiments/segment_index.h"
#include "cogmap/experiments/trajectory_rows.h"
#include "cogmap/mapper/seam/robot_geometry.h"

namespace cogmap::experiments {
namespace {

using mapper::Point2;
using mapper::Pose2;
using mapper::Segment;

// A wall along y = 1 from x = 0 to 10; the robot heads +x with its centre at y = 1 - gap - 0.2525,
// so its left side is `gap` from the wall.
TrajectoryRow row_at(double t_s, double x_m, double gap_m) {
  TrajectoryRow r;
  r.t_s = t_s;
  r.truth = Pose2{x_m, 1.0 - gap_m - 0.2525, 0.0};
  return r;
}

TEST(NavMetrics, ContactEpisodesFromTheTrueFootprint) {
  const std::vector<Segment> wall{{{0.0, 1.0}, {10.0, 1.0}}};
  const mapper::RobotGeometry robot = mapper::p2at_geometry();
  ASSERT_DOUBLE_EQ(robot.width_m, 0.505);
  // Gaps by frame (0.1 s apart): away, two touching frames, away, one touching, then the robot
  // turned 90 deg beside the wall's end (its corner 0.015 m from the wall's end point).
  const std::vector<double> gaps{0.5, 0.3, 0.019, 0.0, 0.1, 1.5, 0.012, 0.03};
  std::vector<TrajectoryRow> rows;
  for (std::size_t i = 0; i < gaps.size(); ++i) rows.push_back(row_at(0.1 * i, 5.0, gaps[i]));
  TrajectoryRow end;
  end.t_s = 0.8;
  end.truth = Pose2{10.0 + 0.2525 + 0.015, 1.0 - 0.313, 1.5707963267948966};
  rows.push_back(end);
  TrajectoryLog log(false);
  for (const TrajectoryRow& r : rows) log.push_back(r);

  const SegmentIndex index(wall, 0.5);
  for (const SegmentIndex* idx : {static_cast<const SegmentIndex*>(nullptr), &index}) {
    NavMetrics nav;
    add_contacts(nav, log.view(), wall, robot, idx);
    // Frames 2-3 touch (one episode), frame 6 (0.012 m) touches, frame 7 (0.03 m) does not, and
    // frame 8 (the corner, 0.015 m) touches again.
    ASSERT_TRUE(nav.contacts.has_value());
    EXPECT_EQ(*nav.contacts, 3u) << (idx ? "indexed" : "plain");
    ASSERT_EQ(nav.contact_start_s.size(), 3u);
    EXPECT_DOUBLE_EQ(nav.contact_start_s[0], 0.2);
    EXPECT_DOUBLE_EQ(nav.contact_start_s[1], 0.1 * 6);
    EXPECT_DOUBLE_EQ(nav.contact_start_s[2], 0.8);
    ASSERT_TRUE(nav.contact_s.has_value());
    EXPECT_NEAR(*nav.contact_s, 0.4, 1e-12);  // each touching frame counts the 0.1 s before it
  }
}

}  // namespace
}  // namespace cogmap::experiments
