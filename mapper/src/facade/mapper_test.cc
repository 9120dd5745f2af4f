#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "cogmap/mapper/mapper.h"
#include "facade/mapper_test_support.h"

namespace cogmap::mapper {
namespace {

using test::drive;
using test::median_wall_error;
using test::rectangle;

TEST(Mapper, OneRoomBecomesOneAsrOnTheTrueWalls) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = rectangle(0.0, 0.0, 6.0, 5.0);
  const auto frames =
      drive({{1.0, 1.0}, {5.0, 1.0}, {5.0, 4.0}, {1.0, 4.0}, {1.0, 1.5}}, walls, robot, 0.0);
  MapperOptions options;
  options.localization = LocalizationKind::kNone;
  MemoryAsrStore store;
  Mapper mapper(options, robot, store, Pose2{});
  int rooms_seen = 0;
  mapper.set_room_listener(
      [&](const Asr& asr, const AsrTrace& trace, const std::optional<Localization>& localized) {
        ++rooms_seen;
        EXPECT_FALSE(localized.has_value());  // localisation off
        EXPECT_EQ(trace.asr_id, asr.id);
        EXPECT_FALSE(trace.extracted.empty());
      });
  for (const SensorFrame& f : frames) mapper.process(f);
  const auto id = mapper.finish();
  ASSERT_TRUE(id.has_value());
  EXPECT_EQ(rooms_seen, 1);
  EXPECT_EQ(store.ids().size(), 1u);
  const auto map = mapper.master_map(true);
  ASSERT_FALSE(map.empty());
  EXPECT_LT(median_wall_error(map, walls), 0.1);
  EXPECT_GT(mapper.stats().readings_used, 0u);
  EXPECT_EQ(mapper.stats().rejected.total(), 0u);
}

TEST(Mapper, BadReadingsAreCountedNotMapped) {
  const RobotGeometry robot = p2at_geometry();
  MapperOptions options;
  MemoryAsrStore store;
  Mapper mapper(options, robot, store, Pose2{});
  SensorFrame f;
  f.time_s = 0.1;
  f.sonar = {{0, std::numeric_limits<double>::quiet_NaN(), true, 0.1},
             {1, -1.0, true, 0.1},
             {2, 99.0, true, 0.1},
             {77, 1.0, true, 0.1}};
  mapper.process(f);
  EXPECT_EQ(mapper.stats().rejected.total(), 4u);
  EXPECT_EQ(mapper.stats().readings_used, 0u);
}

TEST(Mapper, DistanceBoundariesSplitACorridorAndEmUndoesHeadingDrift) {
  const RobotGeometry robot = p2at_geometry();
  // A 2.4 m corridor, 24 m long; the robot drives its centre line.
  const std::vector<Segment> walls{{{-1.0, -1.2}, {25.0, -1.2}}, {{-1.0, 1.2}, {25.0, 1.2}}};
  const double drift = 1.0 * std::numbers::pi / 180.0;  // 1° of heading error per metre
  const auto frames = drive({{0.0, 0.0}, {22.0, 0.0}}, walls, robot, drift);
  auto run = [&](LocalizationKind kind, std::vector<Mapper::MapSegment>* map, Pose2* last) {
    MapperOptions options;
    options.boundary = BoundaryKind::kDistance;
    options.distance.asr_distance_m = 4.0;
    options.localization = kind;
    // 1°/m is ten times the drift model's straight-line walk: the odometry-prior gate would
    // refuse most of it (13° of the 22° stay). This test is about the thesis's EM itself.
    options.localizer.odometry_prior = false;
    MemoryAsrStore store;
    Mapper mapper(options, robot, store, Pose2{});
    for (const SensorFrame& f : frames) mapper.process(f);
    mapper.finish();
    *map = mapper.master_map(true);
    *last = mapper.pose_estimate();
    return store.ids().size();
  };
  std::vector<Mapper::MapSegment> map_odometry, map_em;
  Pose2 last_odometry, last_em;
  EXPECT_GE(run(LocalizationKind::kNone, &map_odometry, &last_odometry), 5u);
  EXPECT_GE(run(LocalizationKind::kEm, &map_em, &last_em), 5u);
  // 22 m at 1°/m leaves odometry 22° off; EM re-aligns every 4 m room to the previous one.
  EXPECT_NEAR(last_odometry.theta_rad, 22.0 * drift, 1e-6);
  EXPECT_LT(std::abs(last_em.theta_rad), std::abs(last_odometry.theta_rad) / 3.0);
  EXPECT_LT(median_wall_error(map_em, walls), median_wall_error(map_odometry, walls));
}

TEST(Mapper, FinishTurnsTheEstimateByTheLastRoomsCorrection) {
  const RobotGeometry robot = p2at_geometry();
  const std::vector<Segment> walls{{{-1.0, -1.2}, {25.0, -1.2}}, {{-1.0, 1.2}, {25.0, 1.2}}};
  const double drift = 1.0 * std::numbers::pi / 180.0;  // 1° per metre, as above
  const auto frames = drive({{0.0, 0.0}, {22.0, 0.0}}, walls, robot, drift);
  MapperOptions options;
  options.boundary = BoundaryKind::kDistance;
  options.distance.asr_distance_m = 4.0;
  options.localization = LocalizationKind::kEm;
  options.localizer.odometry_prior = false;
  MemoryAsrStore store;
  Mapper mapper(options, robot, store, Pose2{});
  for (const SensorFrame& f : frames) mapper.process(f);
  const Pose2 before = mapper.pose_estimate();
  const std::optional<int> last = mapper.finish();
  ASSERT_TRUE(last.has_value());
  const double correction_rad = store.load(*last).heading_correction_rad;
  // The last 2 m drifted 2° that no boundary has corrected yet; closing the room corrects them.
  EXPECT_GT(std::abs(correction_rad), 0.5 * std::numbers::pi / 180.0);
  const Pose2 after = mapper.pose_estimate();
  EXPECT_NEAR(wrap_angle_rad(after.theta_rad - before.theta_rad), correction_rad, 1e-12);
  EXPECT_LT(std::abs(after.theta_rad), std::abs(before.theta_rad));  // the true heading is 0
}

/// One 22 m corridor mapped as a single room (no doorway), odometry drifting `drift_rad_per_m`:
/// the final heading estimate and the map, with or without in-room glimpses.
struct CorridorRun {
  double final_heading_rad = 0.0;
  double median_wall_error_m = 0.0;
  MapperStats stats;
};

CorridorRun map_one_room_corridor(bool glimpses, double drift_rad_per_m, bool scan_match = false,
                                  double drift_model_rad_per_sqrt_m = 0.005) {
  const RobotGeometry robot = p2at_geometry();
  const std::vector<Segment> walls{{{-1.0, -1.2}, {25.0, -1.2}}, {{-1.0, 1.2}, {25.0, 1.2}}};
  const auto frames = drive({{0.0, 0.0}, {22.0, 0.0}}, walls, robot, drift_rad_per_m);
  MapperOptions options;
  options.glimpse.enabled = glimpses;
  options.scan_match.enabled = scan_match;
  options.localizer.drift.rad_per_sqrt_m = drift_model_rad_per_sqrt_m;
  // EM as the glimpses were measured with: the gate alone, against the last 2 rooms (with the
  // posterior mean each glimpse's correction is shrunk toward the odometry prior).
  options.localizer.prior_shrinks = false;
  options.localizer.reference_rooms = 2;
  MemoryAsrStore store;
  Mapper mapper(options, robot, store, Pose2{});
  for (const SensorFrame& f : frames) mapper.process(f);
  CorridorRun out;
  out.final_heading_rad = mapper.pose_estimate().theta_rad;
  mapper.finish();
  out.median_wall_error_m = median_wall_error(mapper.master_map(true), walls);
  out.stats = mapper.stats();
  return out;
}

TEST(Mapper, GlimpsesAreOffByDefault) { EXPECT_FALSE(MapperOptions{}.glimpse.enabled); }

TEST(Mapper, GlimpsesUndoHeadingDriftInsideOneRoom) {
  const double drift = 0.5 * std::numbers::pi / 180.0;  // 0.5° per metre: 11° over the room
  const CorridorRun thesis = map_one_room_corridor(false, drift);
  const CorridorRun glimpses = map_one_room_corridor(true, drift);
  EXPECT_EQ(thesis.stats.rooms, 1u);
  EXPECT_EQ(glimpses.stats.rooms, 1u);
  // Without glimpses nothing corrects inside the room: the estimate is odometry, 11° off.
  EXPECT_NEAR(thesis.final_heading_rad, 22.0 * drift, 1e-6);
  // 3 m glimpses: 7 of them, 6 measured against the ones before. Each sees 1.5° of new drift
  // and the drift keeps growing after the last one: measured 2.3° left of 11°.
  EXPECT_EQ(glimpses.stats.glimpse_corrections, 6u);
  EXPECT_LT(std::abs(glimpses.final_heading_rad), 3.0 * std::numbers::pi / 180.0);
}

TEST(Mapper, GlimpsesLeaveAnUndriftedHeadingAlone) {
  const CorridorRun glimpses = map_one_room_corridor(true, 0.0);
  EXPECT_GE(glimpses.stats.glimpses, 5u);
  // Straight walls seen without drift measure no rotation: the estimate stays on odometry.
  EXPECT_LT(std::abs(glimpses.final_heading_rad), 0.2 * std::numbers::pi / 180.0);
}

TEST(Mapper, ScanMatchingIsOffByDefault) { EXPECT_FALSE(MapperOptions{}.scan_match.enabled); }

TEST(Mapper, ScanMatchingTurnsTheHeadingBackInsideOneRoom) {
  const double drift = 0.5 * std::numbers::pi / 180.0;  // 0.5° per metre: 11° over the room
  const CorridorRun thesis = map_one_room_corridor(false, drift);
  // The matches weigh their echoes against odometry's drift model: the P2-AT's (0.005 rad/√m,
  // a tenth of this drift) holds most of each correction back; one that admits it (0.01) less.
  const CorridorRun held = map_one_room_corridor(false, drift, true);
  const CorridorRun matched = map_one_room_corridor(false, drift, true, 0.01);
  EXPECT_EQ(matched.stats.rooms, 1u);
  EXPECT_NEAR(thesis.final_heading_rad, 22.0 * drift, 1e-6);
  // A match every metre of the estimate's travel: the first has no memory to match.
  EXPECT_EQ(matched.stats.scan_matches, 21u);
  EXPECT_EQ(matched.stats.scan_matches_measured, 20u);
  // Each match measures the drift since the memory beside it was drawn, about 0.5°, and the
  // posterior applies part of it: measured 11° -> 9.3° and 7.9°.
  const double deg = std::numbers::pi / 180.0;
  EXPECT_LT(std::abs(held.final_heading_rad), 9.8 * deg);
  EXPECT_LT(std::abs(matched.final_heading_rad), 8.5 * deg);
  EXPECT_GT(matched.final_heading_rad, 0.0);  // turned back, not past the truth
  EXPECT_LT(matched.median_wall_error_m, thesis.median_wall_error_m);
}

TEST(Mapper, ScanMatchingLeavesAnUndriftedHeadingAlone) {
  const CorridorRun matched = map_one_room_corridor(false, 0.0, true);
  EXPECT_EQ(matched.stats.scan_matches_measured, 20u);
  EXPECT_LT(std::abs(matched.final_heading_rad), 0.2 * std::numbers::pi / 180.0);
}

TEST(Mapper, ARoomLargerThanTheExtentLimitEnds) {
  const RobotGeometry robot = p2at_geometry();
  // A doorway-less 22 m corridor: the doorway detector never fires, so only the extent limit
  // can end a room. With a 6 m limit the path is cut at x = 6, 12 and 18 (the first pose
  // past each 6 m span): four rooms, and no grid ever spans more than 6 m of path + sonar range.
  const std::vector<Segment> walls{{{-1.0, -1.2}, {25.0, -1.2}}, {{-1.0, 1.2}, {25.0, 1.2}}};
  const auto frames = drive({{0.0, 0.0}, {22.0, 0.0}}, walls, robot, 0.0);
  auto rooms = [&](double limit_m, std::size_t* peak_grid_bytes) {
    MapperOptions options;
    options.max_room_extent_m = limit_m;
    MemoryAsrStore store;
    Mapper mapper(options, robot, store, Pose2{});
    for (const SensorFrame& f : frames) mapper.process(f);
    mapper.finish();
    *peak_grid_bytes = mapper.stats().peak_grid_bytes;
    return store.ids().size();
  };
  std::size_t small_peak = 0, default_peak = 0;
  EXPECT_EQ(rooms(6.0, &small_peak), 4u);
  EXPECT_EQ(rooms(MapperOptions{}.max_room_extent_m, &default_peak), 1u);
  EXPECT_LT(small_peak, default_peak);
}

TEST(Mapper, AJumpPastTheExtentLimitStartsTheNextRoomBeforeItIsDrawn) {
  // A log's time gap admits a long odometry jump (1 m + 2 x top speed x the gap): 1400 m in
  // one frame, with a reading timed just after the frame before it. One grid used to hold both
  // ends (a 2800 m jump: gigabytes) and min_room_duration_s could hold the cut off for ever.
  const RobotGeometry robot = p2at_geometry();
  MapperOptions options;
  options.min_room_duration_s = 1e6;
  MemoryAsrStore store;
  Mapper mapper(options, robot, store, Pose2{});
  auto frame = [](double t, double x, double reading_t) {
    SensorFrame f;
    f.time_s = t;
    f.odometry = Pose2{x, x, 0.0};  // diagonal: a grid holding both ends is square
    f.sonar.push_back(SonarReading{0, 1.5, true, reading_t});
    return f;
  };
  EXPECT_FALSE(mapper.process(frame(0.0, 0.0, 0.0)));
  EXPECT_FALSE(mapper.process(frame(0.1, 0.05, 0.1)));
  EXPECT_EQ(mapper.process(frame(700.0, 1000.0, 0.2)), std::optional<int>(0));
  EXPECT_FALSE(mapper.process(frame(700.1, 1000.05, 700.1)));
  mapper.finish();
  EXPECT_EQ(store.ids().size(), 2u);
  // Each grid spans metres, not the kilometre between them (10 cm cells, one byte or more).
  EXPECT_LT(mapper.stats().peak_grid_bytes, 4'000'000u);
}

TEST(Mapper, ARoomToursLongerThanTheTravelLimitAreCut) {
  const RobotGeometry robot = p2at_geometry();
  // A 6 x 5 m room without a door toured one and a half times at 1 m from its walls: 21 m of
  // path in 0.05 m steps, never more than 4 m from the start. The doorway detector never fires
  // (the sides are 0.86 m away or more) and the extent limit is far off, so only the travel
  // limit can end a room: cuts at 4.5, 9.0, 13.5 and 18.0 m (the first frame at or past each
  // 4.5 m of path since the last cut) give five rooms, the last one 3 m long.
  const auto walls = rectangle(0.0, 0.0, 6.0, 5.0);
  const auto frames =
      drive({{1.0, 1.0}, {5.0, 1.0}, {5.0, 4.0}, {1.0, 4.0}, {1.0, 1.0}, {5.0, 1.0}, {5.0, 4.0}},
            walls, robot, 0.0);
  auto room_starts = [&](double limit_m) {
    MapperOptions options;
    options.max_room_travel_m = limit_m;
    MemoryAsrStore store;
    Mapper mapper(options, robot, store, Pose2{});
    std::vector<double> starts{frames.front().time_s};
    for (const SensorFrame& f : frames) {
      if (mapper.process(f)) starts.push_back(f.time_s);
    }
    mapper.finish();
    EXPECT_EQ(store.ids().size(), starts.size());
    return starts;
  };
  EXPECT_EQ(room_starts(0.0).size(), 1u);  // off: one room, as the thesis's doorway rule says
  const std::vector<double> cut = room_starts(4.5);
  ASSERT_EQ(cut.size(), 5u);
  // 4.5 m of path is 90 steps of 0.1 s; the first room starts at the first frame (0.1 s).
  for (std::size_t i = 1; i < cut.size(); ++i) EXPECT_NEAR(cut[i] - cut[i - 1], 9.0, 0.15);
  // With distance cuts the boundary is that rule already, at its own length: 6 m cuts at 6, 12
  // and 18 m make four rooms, whatever max_room_travel_m says.
  MapperOptions distance;
  distance.boundary = BoundaryKind::kDistance;
  distance.distance.asr_distance_m = 6.0;
  distance.max_room_travel_m = 4.5;
  EXPECT_EQ(applied_max_room_travel_m(distance), 0.0);
  MemoryAsrStore store;
  Mapper mapper(distance, robot, store, Pose2{});
  for (const SensorFrame& f : frames) mapper.process(f);
  mapper.finish();
  EXPECT_EQ(store.ids().size(), 4u);
}

/// Two 6 x 5 m rooms side by side, a 1 m door in the wall between them at (6, 2.5). The robot
/// drives from (2, 2.5) through the door to (9.5, 2.5) and back to (2, 2.5); in the second room
/// its odometry drifts 0.3 m north (a ramp from x = 7 to the turn), as a skid-steer's might.
struct DoorRun {
  Pose2 final_estimate;
  MapperStats stats;
};

DoorRun map_two_rooms_through_one_door(const DoorFixOptions& door_fix,
                                       LocalizationKind localization = LocalizationKind::kEm) {
  const RobotGeometry robot = p2at_geometry();
  // The wall between the rooms is 0.12 m thick, as the simulator's: the side sonars' axis rays
  // meet the door frame only along its depth.
  std::vector<Segment> walls = rectangle(0.0, 0.0, 12.0, 5.0);
  for (const double y_jamb : {2.0, 3.0}) {
    const double y_end = y_jamb < 2.5 ? 0.0 : 5.0;
    walls.push_back({{5.94, y_end}, {5.94, y_jamb}});
    walls.push_back({{5.94, y_jamb}, {6.06, y_jamb}});
    walls.push_back({{6.06, y_jamb}, {6.06, y_end}});
  }
  std::vector<SensorFrame> frames = drive({{2.0, 2.5}, {9.5, 2.5}, {2.0, 2.5}}, walls, robot, 0.0);
  std::size_t ramp_start = 0, turn = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (ramp_start == 0 && frames[i].true_pose->x_m > 7.0) ramp_start = i;
    if (frames[i].true_pose->x_m > frames[turn].true_pose->x_m) turn = i;
  }
  for (std::size_t i = ramp_start; i < frames.size(); ++i) {
    const double share =
        std::min(1.0, static_cast<double>(i - ramp_start) / static_cast<double>(turn - ramp_start));
    frames[i].odometry.y_m += 0.3 * share;
  }
  MapperOptions options;
  options.door_fix = door_fix;
  options.localization = localization;
  MemoryAsrStore store;
  Mapper mapper(options, robot, store, Pose2{});
  for (const SensorFrame& f : frames) mapper.process(f);
  return {mapper.pose_estimate(), mapper.stats()};
}

TEST(Mapper, DoorFixesAreOnByDefault) { EXPECT_TRUE(MapperOptions{}.door_fix.enabled); }

// Passed back through the door, the robot measures it 0.3 m north of where it first did: the
// estimate moves back by the fix's gain, which after a long tour (a drift far above two
// passages' scatter) is the whole difference, and by nothing when the fix is off. (EM turns
// room 1, drawn while the odometry drifted, by a fraction of a degree in every run alike.)
TEST(Mapper, ADoorPassedAgainPutsTheEstimateBackWhereTheDoorWas) {
  DoorFixOptions off;
  off.enabled = false;
  const DoorRun thesis = map_two_rooms_through_one_door(off);
  EXPECT_EQ(thesis.stats.door_fixes, 0u);
  EXPECT_NEAR(thesis.final_estimate.y_m, 2.8, 0.03);  // the odometry's drift, and EM's turn

  DoorFixOptions whole;
  whole.drift_sd_per_m = 10.0;  // gain 1 - 2e-4: the door's first measurement is taken as is
  const DoorRun fixed = map_two_rooms_through_one_door(whole);
  EXPECT_EQ(fixed.stats.door_fixes, 1u);
  const double moved_back_m = thesis.final_estimate.y_m - fixed.final_estimate.y_m;
  EXPECT_NEAR(moved_back_m, 0.3, 0.005);  // the axis-ray sonar places the door to 1 mm
  EXPECT_NEAR(fixed.stats.door_fix_abs_m, moved_back_m, 0.01);  // a fix across the door only
  EXPECT_NEAR(fixed.final_estimate.x_m, thesis.final_estimate.x_m, 0.01);

  // The default weighs the drift of the ~6.9 m since the first passage (0.016 m per metre:
  // 0.110 m sd) against two passages' scatter (0.09 m each): gain 0.0122 / (0.0122 + 0.0162)
  // (measured 0.438).
  const DoorRun weighed = map_two_rooms_through_one_door(DoorFixOptions{});
  EXPECT_EQ(weighed.stats.door_fixes, 1u);
  const double gain = (thesis.final_estimate.y_m - weighed.final_estimate.y_m) / moved_back_m;
  EXPECT_NEAR(gain, 0.43, 0.02);
  // With localisation off the estimate is odometry's, door or not.
  const DoorRun odometry = map_two_rooms_through_one_door(whole, LocalizationKind::kNone);
  EXPECT_EQ(odometry.stats.door_fixes, 0u);
  EXPECT_NEAR(odometry.final_estimate.y_m, 2.8, 1e-9);
}

TEST(Mapper, RoomsEndOnlyAtDoorwaysByDefault) {
  EXPECT_EQ(MapperOptions{}.max_room_travel_m, 0.0);  // the thesis's rule (§3.1.2)
}

TEST(Mapper, OdometryIsReportedAsItCameByDefault) {
  EXPECT_EQ(MapperOptions{}.odometry_calibration.curvature_gain, 0.0);
}

/// The odometry pose the mapper ends with after `steps` frames of a constant arc (0.05 m and
/// `turn_rad` per frame, midpoint-integrated as the robot reports it) on `robot`.
Pose2 odometry_after_arc(const RobotGeometry& robot, double gain, double turn_rad, int steps) {
  MapperOptions options;
  options.odometry_calibration.curvature_gain = gain;
  MemoryAsrStore store;
  Mapper mapper(options, robot, store, Pose2{});
  Pose2 raw;
  for (int k = 0; k <= steps; ++k) {
    SensorFrame f;
    f.time_s = 0.1 * k;
    f.odometry = raw;
    mapper.process(f);
    const double mid = raw.theta_rad + 0.5 * turn_rad;
    raw = {raw.x_m + 0.05 * std::cos(mid), raw.y_m + 0.05 * std::sin(mid),
           wrap_angle_rad(raw.theta_rad + turn_rad)};
  }
  return mapper.odometry_pose();
}

TEST(Mapper, ASkidSteersArcsAreReintegratedWithTheCurvatureGain) {
  const RobotGeometry robot = p2at_geometry();  // skid-steer, odometry track 0.588 m
  ASSERT_EQ(robot.drive, DriveKind::kSkidSteer);
  // 0.01 rad per 0.05 m: spin fraction 0.01 · 0.588 / 0.1 = 0.0588, so each turn is the
  // odometry's divided by 1 + 0.05 · (0.0588 - 1): 60 frames of 0.01 rad make 0.63 rad.
  const double s = 0.01 * robot.odometry_track_m / 0.1;
  const Pose2 out = odometry_after_arc(robot, 0.05, 0.01, 60);
  EXPECT_NEAR(out.theta_rad, 60 * 0.01 / (1.0 + 0.05 * (s - 1.0)), 1e-9);
  EXPECT_NEAR(odometry_after_arc(robot, 0.0, 0.01, 60).theta_rad, 0.6, 1e-12);
}

TEST(Mapper, ADifferentialDrivesOdometryIsNeverReintegrated) {
  RobotGeometry robot = p2at_geometry();
  robot.drive = DriveKind::kDifferential;
  const Pose2 out = odometry_after_arc(robot, 0.05, 0.01, 60);
  EXPECT_NEAR(out.theta_rad, 0.6, 1e-12);
}

}  // namespace
}  // namespace cogmap::mapper
