// The crossing's front check: points in the door's band (the jambs and their smear) stop the
// robot only at the crossing's shorter distances; anything beyond the band keeps the route's.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "nav/nav_core.h"
#include "nav/nav_test_util.h"
#include "nav/steering.h"

namespace cogmap::mapper::nav {
namespace {

using testing::kHalfLength;

TEST(LaneClearance, SkipsThePointsInTheDoorBand) {
  // Smear 0.6 m ahead in the door line (x = 0.6), a wall 1.5 m ahead beyond it.
  const std::vector<ObstaclePoint> points = {{Point2(0.6, 0.1), 15.0f},
                                             {Point2(0.6, -0.05), 15.0f},
                                             {Point2(1.5, 0.0), 15.0f},
                                             {Point2(0.4, 0.5), 15.0f}};  // beside the lane
  EXPECT_DOUBLE_EQ(lane_clearance_m(points, 0.0, 0.29, 2.0 * kHalfLength), 0.6 - kHalfLength);
  const DoorBand band{Point2(0.6, 0.0), Point2(1.0, 0.0), 0.3};
  EXPECT_DOUBLE_EQ(lane_clearance_m(points, 0.0, 0.29, 2.0 * kHalfLength, &band),
                   1.5 - kHalfLength);
  // The band is a strip about the door line, not a disc: 0.31 m beyond it counts again.
  const std::vector<ObstaclePoint> beyond = {{Point2(0.91, 0.0), 15.0f}};
  EXPECT_DOUBLE_EQ(lane_clearance_m(beyond, 0.0, 0.29, 2.0 * kHalfLength, &band),
                   0.91 - kHalfLength);
  // Heading 90°: the lane runs along +y, so the same band (normal x) skips nothing there.
  const std::vector<ObstaclePoint> north = {{Point2(0.0, 0.7), 15.0f}};
  EXPECT_DOUBLE_EQ(lane_clearance_m(north, M_PI / 2, 0.29, 2.0 * kHalfLength, &band),
                   0.7 - kHalfLength);
  const DoorBand north_band{Point2(0.0, 0.7), Point2(0.0, 1.0), 0.3};
  EXPECT_DOUBLE_EQ(lane_clearance_m(north, M_PI / 2, 0.29, 2.0 * kHalfLength), 0.7 - kHalfLength);
  EXPECT_DOUBLE_EQ(lane_clearance_m(north, M_PI / 2, 0.29, 2.0 * kHalfLength, &north_band),
                   std::numeric_limits<double>::infinity());
}

/// A core that has sensed the two front (±10°) transducers' echoes at `range_m`, robot at the
/// origin facing +x.
struct SensedCore {
  RobotGeometry robot = p2at_geometry();
  SensorFrame frame;
  NavCore core{CoreOptions{}};
  NavInput input;
  double lane_m = 0.0;  // bumper to the nearest field point in the 0.29 m lane

  explicit SensedCore(double range_m) {
    frame.time_s = 0.0;
    frame.sonar = {{3, range_m, true, 0.0}, {4, range_m, true, 0.0}};
    input.frame = &frame;
    input.robot = &robot;
    core.sense(input);
    lane_m = std::numeric_limits<double>::infinity();
    for (const ObstaclePoint& p : core.field().points()) {
      if (p.offset_m.x() > 0.0 && std::abs(p.offset_m.y()) <= 0.29) {
        lane_m = std::min(lane_m, p.offset_m.x() - kHalfLength);
      }
    }
  }
};

TEST(DoorCross, SmearInTheDoorBandSlowsTheCrossingOnlyNearIt) {
  // Echoes 0.5 m from the front transducers: about 0.44 m from the bumper, inside the lane.
  SensedCore s(0.5);
  ASSERT_GT(s.lane_m, 0.36);
  ASSERT_LT(s.lane_m, 0.50);
  const double speed = 0.3;  // DoorOptions::speed_mps
  const CoreOptions o;
  // No band: the route's stop (0.35 m) and slow (1.0 m) distances.
  const VelocityCommand plain = s.core.drive_direct(s.input, 0.0, speed, NavMode::kDoorCross);
  EXPECT_NEAR(plain.v_mps,
              speed * (s.lane_m - o.safety.stop_clearance_m) /
                  (o.safety.slow_clearance_m - o.safety.stop_clearance_m),
              1e-9);
  // The echoes lie in the door line: the crossing's distances (0.25 m, 0.6 m) apply.
  const double door_x = s.lane_m + kHalfLength;
  const DoorBand band{Point2(door_x, 0.0), Point2(1.0, 0.0), 0.3};
  const VelocityCommand crossing =
      s.core.drive_direct(s.input, 0.0, speed, NavMode::kDoorCross, &band);
  EXPECT_NEAR(crossing.v_mps,
              speed * (s.lane_m - o.cross_stop_clearance_m) /
                  (o.cross_slow_clearance_m - o.cross_stop_clearance_m),
              1e-9);
  EXPECT_GT(crossing.v_mps, 3.0 * plain.v_mps);
  EXPECT_DOUBLE_EQ(crossing.w_radps, 0.0);
  // The same echoes with the door a metre further: they are in the way, not in the door.
  const DoorBand far{Point2(door_x + 1.0, 0.0), Point2(1.0, 0.0), 0.3};
  const VelocityCommand blocked =
      s.core.drive_direct(s.input, 0.0, speed, NavMode::kDoorCross, &far);
  EXPECT_DOUBLE_EQ(blocked.v_mps, plain.v_mps);
  // Outside a crossing the band is not looked at: the ±30° front check applies as before.
  const VelocityCommand align =
      s.core.drive_direct(s.input, 0.0, speed, NavMode::kDoorAlign, &band);
  const double front = s.core.trace().front_clearance_m;
  EXPECT_NEAR(align.v_mps,
              speed * std::clamp((front - o.safety.stop_clearance_m) /
                                     (o.safety.slow_clearance_m - o.safety.stop_clearance_m),
                                 0.0, 1.0),
              1e-9);
  EXPECT_LT(align.v_mps, crossing.v_mps);
}

TEST(DoorCross, StopsShortOfTheJambsEvenInTheBand) {
  // Echoes 0.3 m from the transducers: ~0.25 m from the bumper, at the crossing's stop.
  SensedCore s(0.25);
  ASSERT_LT(s.lane_m, CoreOptions{}.cross_stop_clearance_m);
  const DoorBand band{Point2(s.lane_m + kHalfLength, 0.0), Point2(1.0, 0.0), 0.3};
  const VelocityCommand cmd = s.core.drive_direct(s.input, 0.0, 0.3, NavMode::kDoorCross, &band);
  EXPECT_DOUBLE_EQ(cmd.v_mps, 0.0);
}

}  // namespace
}  // namespace cogmap::mapper::nav
