// Free-space clearing in the obstacle memory (MemoryOptions clear_*): a later reading that runs
// past a remembered echo along the core of its transducer's beam removes it. Exact geometry:
// one transducer at (0.2, 0.1) looking along the robot's +x axis, robot at the origin unless
// said otherwise, so a remembered echo at world (x, 0.1) lies x - 0.2 along that axis.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "cogmap/test_support/angles.h"
#include "nav/nav_test_util.h"
#include "nav/obstacle_memory.h"

namespace cogmap::mapper::nav {
namespace {

constexpr double kMountX = 0.2;
constexpr double kMountY = 0.1;

RobotGeometry one_mount() {
  RobotGeometry robot;
  robot.sonars = {{kMountX, kMountY, 0.0}};
  return robot;
}

using testing::frame;

SonarReading echo(int index, double range_m) { return {index, range_m, true, 0.0}; }
SonarReading no_echo(int index) { return {index, 5.0, false, 0.0}; }

/// Remembers one echo of transducer 0 at world (x_m, y_m): the robot is placed so that the
/// echo lies 1.0 m along the transducer's axis.
void remember_at(ObstacleMemory& memory, double time_s, double x_m, double y_m,
                 const RobotGeometry& robot) {
  const Pose2 pose{x_m - kMountX - 1.0, y_m - kMountY, 0.0};
  memory.add_frame(frame(time_s, {echo(0, 1.0)}), pose, robot);
}

bool remembers(const ObstacleMemory& memory, double x_m, double y_m) {
  for (const ObstacleMemory::Hit& h : memory.hits()) {
    if (std::abs(h.world_m.x() - x_m) < 1e-9 && std::abs(h.world_m.y() - y_m) < 1e-9) return true;
  }
  return false;
}

TEST(ObstacleMemoryClearing, ALongerReadingRemovesAnEchoShortOfItOnTheAxis) {
  const RobotGeometry robot = one_mount();
  ObstacleMemory memory{MemoryOptions{}};
  memory.add_frame(frame(0.0, {echo(0, 1.8)}), {}, robot);  // (2.0, 0.1)
  ASSERT_TRUE(remembers(memory, 2.0, 0.1));
  // 2.5 m: free to 2.3 m along the axis, past the echo at 1.8 m.
  memory.add_frame(frame(0.1, {echo(0, 2.5)}), {}, robot);
  ASSERT_EQ(memory.hits().size(), 1u);
  EXPECT_TRUE(remembers(memory, 2.7, 0.1));  // only the new echo
}

TEST(ObstacleMemoryClearing, KeepsAnEchoBeyondTheReadingOrWithinTheMargin) {
  const RobotGeometry robot = one_mount();
  // Echo 1.8 m along the axis; clear_margin_m = 0.2, so a reading must exceed 2.0 m.
  for (const double later : {1.5, 1.99}) {
    ObstacleMemory memory{MemoryOptions{}};
    memory.add_frame(frame(0.0, {echo(0, 1.8)}), {}, robot);
    memory.add_frame(frame(0.1, {echo(0, later)}), {}, robot);
    EXPECT_EQ(memory.hits().size(), 2u) << later;
    EXPECT_TRUE(remembers(memory, 2.0, 0.1)) << later;
  }
  ObstacleMemory memory{MemoryOptions{}};
  memory.add_frame(frame(0.0, {echo(0, 1.8)}), {}, robot);
  memory.add_frame(frame(0.1, {echo(0, 2.01)}), {}, robot);
  EXPECT_FALSE(remembers(memory, 2.0, 0.1));
  EXPECT_EQ(memory.hits().size(), 1u);

  // A wider margin keeps what the default one clears.
  MemoryOptions wide;
  wide.clear_margin_m = 0.3;
  ObstacleMemory kept{wide};
  kept.add_frame(frame(0.0, {echo(0, 1.8)}), {}, robot);
  kept.add_frame(frame(0.1, {echo(0, 2.05)}), {}, robot);
  EXPECT_TRUE(remembers(kept, 2.0, 0.1));
}

// The cleared band is max(clear_min_half_width_m, along·tan(clear_half_angle_deg)) either side
// of the axis: 1.8 m along, 1.8·tan 3° = 0.0943 m; 0.3 m along, the 0.05 m minimum.
TEST(ObstacleMemoryClearing, KeepsAnEchoOffTheAxisBeyondTheBeamCore) {
  const RobotGeometry robot = one_mount();
  const double half_far = 1.8 * std::tan(3.0 * kPi / 180.0);
  struct Case {
    double x_m, lateral_m;
    bool cleared;
  };
  for (const Case& c : {Case{2.0, half_far - 0.005, true}, Case{2.0, -(half_far - 0.005), true},
                        Case{2.0, half_far + 0.005, false}, Case{2.0, -(half_far + 0.005), false},
                        Case{0.5, 0.045, true}, Case{0.5, -0.045, true}, Case{0.5, 0.055, false},
                        Case{0.5, -0.055, false}}) {
    ObstacleMemory memory{MemoryOptions{}};
    remember_at(memory, 0.0, c.x_m, kMountY + c.lateral_m, robot);
    ASSERT_TRUE(remembers(memory, c.x_m, kMountY + c.lateral_m));
    memory.add_frame(frame(0.1, {no_echo(0)}), {}, robot);
    EXPECT_EQ(remembers(memory, c.x_m, kMountY + c.lateral_m), !c.cleared)
        << c.x_m << " " << c.lateral_m;
  }
}

TEST(ObstacleMemoryClearing, AReadingWithoutEchoClearsUpToClearMax) {
  const RobotGeometry robot = one_mount();
  // Default clear_max_m = 3.0: echoes at 2.9 m and 3.1 m along the axis.
  ObstacleMemory memory{MemoryOptions{}};
  remember_at(memory, 0.0, kMountX + 3.1, kMountY, robot);
  remember_at(memory, 0.1, kMountX + 2.9, kMountY, robot);
  ASSERT_EQ(memory.hits().size(), 2u);
  memory.add_frame(frame(0.2, {no_echo(0)}), {}, robot);
  ASSERT_EQ(memory.hits().size(), 1u);
  EXPECT_TRUE(remembers(memory, kMountX + 3.1, kMountY));

  MemoryOptions shorter;
  shorter.clear_max_m = 1.5;
  ObstacleMemory near{shorter};
  remember_at(near, 0.0, kMountX + 1.6, kMountY, robot);
  remember_at(near, 0.1, kMountX + 1.4, kMountY, robot);
  near.add_frame(frame(0.2, {no_echo(0)}), {}, robot);
  ASSERT_EQ(near.hits().size(), 1u);
  EXPECT_TRUE(remembers(near, kMountX + 1.6, kMountY));
}

TEST(ObstacleMemoryClearing, NeverClearsAContact) {
  RobotGeometry robot = one_mount();
  robot.sonars[0] = {0.0, 0.0, 0.0};  // on the centre line, through the middle contact point
  ObstacleMemory memory{MemoryOptions{}};
  memory.add_contact({}, robot, 0.0, true);  // (0.363, -0.202), (0.363, 0), (0.363, 0.202)
  memory.add_frame(frame(0.0, {echo(0, 1.0)}), {}, robot);
  ASSERT_EQ(memory.hits().size(), 4u);
  memory.add_frame(frame(0.1, {no_echo(0)}), {}, robot);
  // The echo at 1.0 m is gone; the contact on the axis at 0.363 m stays.
  ASSERT_EQ(memory.hits().size(), 3u);
  for (const ObstacleMemory::Hit& h : memory.hits()) EXPECT_TRUE(h.contact);
  EXPECT_TRUE(remembers(memory, 0.5 * robot.length_m + 0.05, 0.0));
}

TEST(ObstacleMemoryClearing, ZeroHalfAngleDisablesClearing) {
  const RobotGeometry robot = one_mount();
  MemoryOptions off;
  off.clear_half_angle_deg = 0.0;
  ObstacleMemory memory{off};
  memory.add_frame(frame(0.0, {echo(0, 1.8)}), {}, robot);
  memory.add_frame(frame(0.1, {echo(0, 2.5)}), {}, robot);
  memory.add_frame(frame(0.2, {no_echo(0)}), {}, robot);
  EXPECT_EQ(memory.hits().size(), 2u);
  EXPECT_TRUE(remembers(memory, 2.0, 0.1));
}

// Each reading clears along its own transducer's axis, placed with the pose: two mounts, the
// robot at (1, 2) facing north. Transducer 0 at (0.2, 0.1) looks north from (0.9, 2.2);
// transducer 1 at (0, 0.25) looks left, i.e. west, from (0.75, 2).
TEST(ObstacleMemoryClearing, ClearsAlongEachTransducersOwnAxisInTheWorld) {
  RobotGeometry robot;
  robot.sonars = {{0.2, 0.1, 0.0}, {0.0, 0.25, kPi / 2}};
  const Pose2 pose{1.0, 2.0, kPi / 2};
  ObstacleMemory memory{MemoryOptions{}};
  memory.add_frame(frame(0.0, {echo(0, 1.5), echo(1, 1.5)}), pose, robot);
  ASSERT_EQ(memory.hits().size(), 2u);
  ASSERT_TRUE(remembers(memory, 0.9, 3.7));
  ASSERT_TRUE(remembers(memory, -0.75, 2.0));
  memory.add_frame(frame(0.1, {no_echo(1)}), pose, robot);
  ASSERT_EQ(memory.hits().size(), 1u);
  EXPECT_TRUE(remembers(memory, 0.9, 3.7));
  memory.add_frame(frame(0.2, {no_echo(0)}), pose, robot);
  EXPECT_TRUE(memory.hits().empty());
}

// One frame's beams all clear, and the expired hits go in the same pass: the memory keeps the
// rest in their order. Two mounts as above, the robot at (1, 2) facing north.
TEST(ObstacleMemoryClearing, OneFrameClearsWithEveryBeamAndForgetsTheExpired) {
  RobotGeometry robot;
  robot.sonars = {{0.2, 0.1, 0.0}, {0.0, 0.25, kPi / 2}};
  const Pose2 pose{1.0, 2.0, kPi / 2};
  MemoryOptions options;
  ObstacleMemory memory{options};
  // An old echo east of the robot, behind both beams, forgotten by the time of the last frame.
  memory.add_frame(frame(0.0, {echo(1, 1.0)}), {3.0, 2.0, kPi / 2}, robot);  // (1.75, 2)
  const double later_s = 0.5 * options.keep_s;
  memory.add_frame(frame(later_s, {echo(0, 1.5), echo(1, 1.5)}), pose, robot);
  // One more, south-east (transducer 0 from (4, 0) facing south: mount (0.2, 0.1) turned),
  // off both beams and still fresh at the end.
  memory.add_frame(frame(later_s, {echo(0, 1.0)}), {4.0, 0.0, -kPi / 2}, robot);
  ASSERT_EQ(memory.hits().size(), 4u);
  const ObstacleMemory::Hit last = memory.hits().back();
  memory.add_frame(frame(options.keep_s + 0.01, {no_echo(0), no_echo(1)}), pose, robot);
  ASSERT_EQ(memory.hits().size(), 1u);
  EXPECT_EQ(memory.hits().front().world_m, last.world_m);
}

}  // namespace
}  // namespace cogmap::mapper::nav
