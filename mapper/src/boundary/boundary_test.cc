#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "cogmap/mapper/boundary/asr_boundary_detector.h"

namespace cogmap::mapper {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Distance (m) from the robot's centre line to the nearest obstacle on one side, as a
/// function of the robot's x (the robot drives along +x at y = 0, heading 0).
using SideWorld = std::function<double(double x_m)>;

/// Drives the robot from x = 0 to `end_x_m` at 0.5 m/s with 10 Hz frames. The four side sonars
/// of the P2-AT (0, 15 left; 7, 8 right) each fire every 0.4 s, staggered by 0.1 s, so a side
/// gets a fresh reading every 0.2 s: the sparse firing of a real ring.
/// The sonars are silent for sonar_stop_x_m <= x < sonar_resume_x_m; `event_x_m`, when given,
/// receives the robot's x at each event.
std::vector<BoundaryEvent> drive(AsrBoundaryDetector& detector, const SideWorld& left,
                                 const SideWorld& right, double end_x_m, bool sonar_after_x = true,
                                 double sonar_stop_x_m = kInf, double sonar_resume_x_m = kInf,
                                 std::vector<double>* event_x_m = nullptr) {
  const RobotGeometry robot = p2at_geometry();
  const int side_sonars[4] = {0, 7, 15, 8};
  std::vector<BoundaryEvent> events;
  for (int k = 0;; ++k) {
    const double t = 0.1 * k;
    const double x = 0.05 * k;
    if (x > end_x_m + 1e-9) break;
    SensorFrame frame;
    frame.time_s = t;
    frame.odometry = {x, 0.0, 0.0};
    const int slot = k % 4;
    const int index = side_sonars[slot];
    if (sonar_after_x && (x < sonar_stop_x_m || x >= sonar_resume_x_m)) {
      const SonarMount& m = robot.sonars[index];
      const double free_m = m.y_m > 0 ? left(x + m.x_m) : right(x + m.x_m);
      const double range_m = free_m - std::abs(m.y_m);
      SonarReading r{index, robot.sonar_max_range_m, false, t};
      if (range_m < robot.sonar_max_range_m) r = {index, range_m, true, t};
      frame.sonar.push_back(r);
    }
    if (auto e = detector.update(frame, frame.odometry)) {
      events.push_back(*e);
      if (event_x_m) event_x_m->push_back(x);
    }
  }
  return events;
}

/// Two 5 m wide rooms joined at x = 5 by a 0.9 m doorway through a 0.4 m thick wall.
double room_door_room(double x_m) { return std::abs(x_m - 5.0) <= 0.2 ? 0.45 : 2.5; }

TEST(DoorwayDetector, RoomDoorRoomGivesExactlyOneEventAtTheDoor) {
  auto detector = make_doorway_detector(DoorwayOptions{}, p2at_geometry());
  const auto events = drive(*detector, room_door_room, room_door_room, 10.0);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0].exit_center.x(), 5.0, 0.35);
  EXPECT_NEAR(events[0].exit_center.y(), 0.0, 1e-9);
  EXPECT_NEAR(events[0].exit_width_m, 0.9, 1e-9);
  EXPECT_NEAR(events[0].heading_rad, 0.0, 1e-12);
  // The event comes after the door, not in the next room's middle.
  EXPECT_GT(events[0].time_s, 10.0);
  EXPECT_LT(events[0].time_s, 12.0);
}

// The robot's x at frame k of a trajectory that drives into the doorway of room_door_room to
// x = 4.95 (inside the frame), backs out to x = 3.0, then drives through to x = 7.
double in_back_out_through(int k) {
  const double t = 0.1 * k;
  if (t <= 9.9) return 0.05 * k;                      // 0 -> 4.95 at 0.5 m/s
  if (t <= 9.9 + 3.9) return 4.95 - 0.05 * (k - 99);  // back to 3.0
  return 3.0 + 0.05 * (k - 138);                      // forward through the door
}

TEST(DoorwayDetector, BackingOutOfADoorIsNoNewRoom) {
  auto detector = make_doorway_detector(DoorwayOptions{}, p2at_geometry());
  const RobotGeometry robot = p2at_geometry();
  const int side_sonars[4] = {0, 7, 15, 8};
  std::vector<double> event_x;
  for (int k = 0; in_back_out_through(k) <= 7.0; ++k) {
    const double x = in_back_out_through(k);
    SensorFrame frame;
    frame.time_s = 0.1 * k;
    frame.odometry = {x, 0.0, 0.0};
    const int index = side_sonars[k % 4];
    const SonarMount& m = robot.sonars[index];
    const double range_m = room_door_room(x + m.x_m) - std::abs(m.y_m);
    frame.sonar.push_back({index, range_m, true, frame.time_s});
    if (detector->update(frame, frame.odometry)) event_x.push_back(x);
  }
  // Backing out (both sides close, then free, 3.9 m of travel) made no room; the pass did.
  ASSERT_EQ(event_x.size(), 1u);
  EXPECT_GT(event_x[0], 5.2);
  EXPECT_LT(event_x[0], 5.8);
}

TEST(DoorwayDetector, AsymmetricDoorCentreIsBetweenTheFrames) {
  auto detector = make_doorway_detector(DoorwayOptions{}, p2at_geometry());
  // Left frame 0.3 m away, right 0.7 m: the gap centre is 0.2 m to the right of the robot.
  const SideWorld left = [](double x) { return std::abs(x - 5.0) <= 0.2 ? 0.3 : 2.5; };
  const SideWorld right = [](double x) { return std::abs(x - 5.0) <= 0.2 ? 0.7 : 2.5; };
  const auto events = drive(*detector, left, right, 10.0);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0].exit_center.y(), -0.2, 1e-9);
  EXPECT_NEAR(events[0].exit_width_m, 1.0, 1e-9);
}

TEST(DoorwayDetector, CorridorGivesOneEventWhenLeaving) {
  auto detector = make_doorway_detector(DoorwayOptions{}, p2at_geometry());
  // A 1.2 m wide corridor from x = 0 to 4, then an open hall.
  const SideWorld corridor = [](double x) { return x < 4.0 ? 0.6 : 3.0; };
  const auto events = drive(*detector, corridor, corridor, 9.0);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_GT(events[0].time_s, 8.0);  // the robot left the corridor at x = 4 (t = 8 s)
  EXPECT_LT(events[0].time_s, 9.5);
}

TEST(DoorwayDetector, ShortCorridorStartIsNoNewRoom) {
  auto detector = make_doorway_detector(DoorwayOptions{}, p2at_geometry());
  // The robot starts in a 1 m long passage: less than min_room_travel_m travelled.
  const SideWorld passage = [](double x) { return x < 0.8 ? 0.6 : 3.0; };
  EXPECT_TRUE(drive(*detector, passage, passage, 6.0).empty());
}

TEST(DoorwayDetector, WallOnOneSideOnlyGivesNone) {
  auto detector = make_doorway_detector(DoorwayOptions{}, p2at_geometry());
  const SideWorld wall = [](double) { return 0.5; };
  const SideWorld open = [](double) { return 3.0; };
  EXPECT_TRUE(drive(*detector, wall, open, 10.0).empty());
  detector->reset();
  EXPECT_TRUE(drive(*detector, open, wall, 10.0).empty());
}

TEST(DoorwayDetector, StaleReadingsAreUnknownNotFree) {
  auto detector = make_doorway_detector(DoorwayOptions{}, p2at_geometry());
  // The sonars stop firing just after the door: the held close readings age out, and without
  // fresh evidence of ¬L ∧ ¬R the robot never leaves the access point.
  const auto events = drive(*detector, room_door_room, room_door_room, 10.0, true, 5.1);
  EXPECT_TRUE(events.empty());
  // ... and it did enter it: once fresh readings come back (x >= 8 m, the second room), the
  // access point is left and the one event fires there, not while the readings were stale.
  detector->reset();
  std::vector<double> at_x;
  const auto resumed =
      drive(*detector, room_door_room, room_door_room, 10.0, true, 5.1, 8.0, &at_x);
  ASSERT_EQ(resumed.size(), 1u);
  EXPECT_GE(at_x[0], 8.0);
  EXPECT_NEAR(resumed[0].exit_center.x(), 5.0, 0.35);
}

TEST(DoorwayDetector, ResetForgetsTheAccessPoint) {
  auto detector = make_doorway_detector(DoorwayOptions{}, p2at_geometry());
  drive(*detector, room_door_room, room_door_room, 5.1);  // stop inside the door
  detector->reset();
  const SideWorld open = [](double) { return 3.0; };
  EXPECT_TRUE(drive(*detector, open, open, 5.0).empty());
}

TEST(DistanceDetector, FiresEveryFourAndAHalfMetres) {
  auto detector = make_distance_detector(DistanceOptions{});
  std::vector<double> at_x;
  for (int k = 0; k <= 44; ++k) {  // 0.25 m steps: exact in binary, 11 m in all
    SensorFrame frame;
    frame.time_s = 0.5 * k;
    const Pose2 pose{0.25 * k, 0.0, 0.3};
    if (auto e = detector->update(frame, pose)) {
      at_x.push_back(pose.x_m);
      EXPECT_DOUBLE_EQ(e->exit_center.x(), pose.x_m);
      EXPECT_DOUBLE_EQ(e->heading_rad, 0.3);
      EXPECT_EQ(e->exit_width_m, 0.0);
    }
  }
  ASSERT_EQ(at_x.size(), 2u);
  EXPECT_DOUBLE_EQ(at_x[0], 4.5);
  EXPECT_DOUBLE_EQ(at_x[1], 9.0);
}

TEST(DistanceDetector, CountsPathLengthNotDisplacement) {
  auto detector = make_distance_detector(DistanceOptions{});
  // Back and forth along 1 m: 4.5 m of path after 4.5 legs, with no net displacement.
  int fired_at = -1;
  for (int k = 0; k <= 20 && fired_at < 0; ++k) {
    const Pose2 pose{(k % 2) * 1.0, 0.0, 0.0};
    if (detector->update(SensorFrame{}, pose)) fired_at = k;
  }
  EXPECT_EQ(fired_at, 5);
}

}  // namespace
}  // namespace cogmap::mapper
