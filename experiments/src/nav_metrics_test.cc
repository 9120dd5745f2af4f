// Contact episodes from the true footprint: a P2-AT (0.626 x 0.505 m) driven past a wall at
// known distances, so which frames touch is known by hand.
#include "cogmap/experiments/nav_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
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
TrajectoryRow nav_row_at(double t_s, double x_m, double gap_m) {
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
  for (std::size_t i = 0; i < gaps.size(); ++i) rows.push_back(nav_row_at(0.1 * i, 5.0, gaps[i]));
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

// How each episode began: the mode in force at its first frame (from the mode changes by row)
// and the touching point of the outline in the body frame.
TEST(NavMetrics, ContactOnsetsNameTheModeAndThePlaceOnTheBody) {
  const std::vector<Segment> wall{{{0.0, 1.0}, {10.0, 1.0}}};
  const mapper::RobotGeometry robot = mapper::p2at_geometry();
  std::vector<TrajectoryRow> rows;
  // Rows 0-3: the left side nears the wall and touches at row 2 (the whole side at 0.019 m:
  // the nearest point is one end of it).
  for (const double gap : {0.5, 0.3, 0.019, 0.5})
    rows.push_back(nav_row_at(0.1 * rows.size(), 5.0, gap));
  // Row 4: turned to face +y beside the wall's end, the front-left corner 0.015 m from it.
  TrajectoryRow end;
  end.t_s = 0.4;
  end.truth = Pose2{10.0 + 0.2525 + 0.015, 1.0 - 0.313, 1.5707963267948966};
  rows.push_back(end);
  // Row 5 away again; row 6: backed into the wall from below, heading -80° (facing down and a
  // little right), so the rear-left corner, 0.352 m above the centre, comes 0.01 m from it.
  rows.push_back(nav_row_at(0.5, 5.0, 0.5));
  const double heading = -80.0 * std::numbers::pi / 180.0;
  const double corner_up_m =
      std::sin(heading) * -0.313 + std::cos(heading) * 0.2525;  // the rear-left corner's y
  TrajectoryRow back;
  back.t_s = 0.6;
  back.truth = Pose2{5.0, 1.0 - corner_up_m - 0.01, heading};
  rows.push_back(back);
  TrajectoryLog log(false);
  for (const TrajectoryRow& r : rows) log.push_back(r);
  using mapper::nav::NavMode;
  const std::vector<ModeChange> modes{
      {1, NavMode::kDrive}, {4, NavMode::kDoorProbe}, {6, NavMode::kBackOff}};

  NavMetrics nav;
  add_contacts(nav, log.view(), wall, robot, nullptr, modes);
  ASSERT_EQ(nav.contact_onsets.size(), 3u);
  EXPECT_DOUBLE_EQ(nav.contact_onsets[0].t_s, 0.2);
  EXPECT_EQ(nav.contact_onsets[0].mode, "drive");
  EXPECT_NEAR(nav.contact_onsets[0].body_m.y(), 0.2525, 1e-9);  // the left side
  EXPECT_NEAR(std::abs(nav.contact_onsets[0].body_m.x()), 0.313, 1e-9);
  EXPECT_EQ(nav.contact_onsets[1].mode, "door_probe");
  EXPECT_NEAR(nav.contact_onsets[1].body_m.x(), 0.313, 1e-9);  // the front-left corner
  EXPECT_NEAR(nav.contact_onsets[1].body_m.y(), 0.2525, 1e-9);
  EXPECT_EQ(nav.contact_onsets[2].mode, "back_off");
  EXPECT_NEAR(nav.contact_onsets[2].body_m.x(), -0.313, 1e-9);  // the rear-left corner
  EXPECT_NEAR(nav.contact_onsets[2].body_m.y(), 0.2525, 1e-9);

  // Without modes, and for rows before the first change, the mode is unknown.
  NavMetrics bare;
  add_contacts(bare, log.view(), wall, robot);
  ASSERT_EQ(bare.contact_onsets.size(), 3u);
  EXPECT_EQ(bare.contact_onsets[0].mode, "unknown");
  const std::vector<ModeChange> late{{5, NavMode::kDrive}};
  NavMetrics partly;
  add_contacts(partly, log.view(), wall, robot, nullptr, late);
  EXPECT_EQ(partly.contact_onsets[1].mode, "unknown");
  EXPECT_EQ(partly.contact_onsets[2].mode, "drive");
}

TEST(NavMetrics, TheNearestOutlinePointOfACrossingIsWhereTheyCross) {
  const mapper::RobotGeometry robot = mapper::p2at_geometry();
  // A wall through the body's right side at x = 0.1 (body frame), robot at the origin facing +x.
  const std::vector<Segment> wall{{{0.1, -0.2}, {0.1, -1.0}}};
  const auto p = nearest_outline_point(Pose2{0.0, 0.0, 0.0}, wall, robot);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x(), 0.1, 1e-9);
  EXPECT_NEAR(p->y(), -0.2525, 1e-9);
  EXPECT_FALSE(nearest_outline_point(Pose2{}, {}, robot).has_value());
}

}  // namespace
}  // namespace cogmap::experiments
