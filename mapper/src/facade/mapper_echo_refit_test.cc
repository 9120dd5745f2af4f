// EM's wall directions refitted to the room's echoes (LocalizerOptions::echo_refit), through the
// facade: a corridor at 7° to the grid's axes driven with exact odometry and an exact sonar (the
// axis ray: every echo lies on a wall), so every heading correction EM makes is the error of its
// measurement. The grid's cells staircase a wall at 7°; the echoes do not.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cogmap/mapper/mapper.h"
#include "cogmap/test_support/angles.h"
#include "facade/mapper_test_support.h"

namespace cogmap::mapper {
namespace {

struct Corrections {
  int rooms = 0;
  double mean_abs_rad = 0.0;
};

Corrections corridor_corrections(double echo_refit_band_m) {
  const RobotGeometry robot = p2at_geometry();
  const double heading_rad = 7.0 * kDeg;
  const Point2 along(std::cos(heading_rad), std::sin(heading_rad));
  const Point2 left(-along.y(), along.x());
  const std::vector<Segment> walls{{-1.0 * along - 1.2 * left, 25.0 * along - 1.2 * left},
                                   {-1.0 * along + 1.2 * left, 25.0 * along + 1.2 * left}};
  const auto frames = test::drive({{0.0, 0.0}, 22.0 * along}, walls, robot, 0.0);
  MapperOptions options;
  options.boundary = BoundaryKind::kDistance;
  options.distance.asr_distance_m = 4.0;
  options.localization = LocalizationKind::kEm;
  options.localizer.odometry_prior = false;  // every measurement applied whole
  options.localizer.echo_refit.band_m = echo_refit_band_m;
  MemoryAsrStore store;
  Mapper mapper(options, robot, store, Pose2{});
  for (const SensorFrame& f : frames) mapper.process(f);
  const std::optional<int> last = mapper.finish();
  Corrections c;
  for (int id = 1; last && id <= *last; ++id) {  // room 0 is the reference: never corrected
    c.mean_abs_rad += std::abs(store.load(id).heading_correction_rad);
    ++c.rooms;
  }
  if (c.rooms > 0) c.mean_abs_rad /= c.rooms;
  return c;
}

TEST(MapperEchoRefit, RoomsMeasuredFromTheirEchoesAreCorrectedLessWhenNothingDrifted) {
  const Corrections fitted = corridor_corrections(0.0);
  const Corrections refitted = corridor_corrections(0.12);
  // 22 m in 4 m rooms: rooms 1-5 after the reference room 0.
  ASSERT_EQ(fitted.rooms, 5);
  ASSERT_EQ(refitted.rooms, 5);
  // Measured 0.0172° against 0.0076° (exact inputs: the same every run). Without the room's
  // echoes (not kept, or kept in another frame) the refit leaves the fitted walls and the two
  // are equal.
  EXPECT_GT(fitted.mean_abs_rad, 0.01 * kDeg);
  EXPECT_LT(refitted.mean_abs_rad, 0.6 * fitted.mean_abs_rad);
}

}  // namespace
}  // namespace cogmap::mapper
