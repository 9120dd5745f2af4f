// The Player importer against Player 3's `ranger` interface as its writelog driver writes it
// (server/drivers/shell/writelog.cc, WriteRanger), from Stage 4 (libstageplugin's p_ranger.cc:
// a sonar ring is one ranger with a pose per sensor and one range each, a laser one sensor with
// every range). Geometry (type 4 subtype 1): "%+07.3f " x 9 (device pose px py pz proll ppitch
// pyaw, size sw sl sh), "%04d " poses, "%+07.3f " x 6 each, "%04d " sizes, "%+07.3f " x 3 each.
// Config (4:5): "%lf " x 7. Ranges (1:1) and intensities (1:3): "%04d ", then "%.3f " each.
// Before, every ranger line was skipped: a Stage 4 log imported with no readings.
#include <gtest/gtest.h>

#include <string>

#include "cogmap/hw/log_import.h"
#include "import_test_files.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;

fs::path ranger_log(const std::string& name, const std::string& text) {
  return testing::write_log("player_ranger_test", name, text);
}

std::string ranger_error_of(const fs::path& p) {
  return testing::import_error([](const fs::path& f) { return import_player_log(f); }, p);
}

const std::string kRangerHeader = testing::writelog_header("3.0.2");

// WriteGeometries, in the order of writelog's `requires`: position2d:0, ranger:0 (the sonar
// ring, 4 sensors), its config (15° beams, 5 m), ranger:1 (the laser, 1 sensor), its config.
// Lines 9 to 13.
const std::string kRangerPositionGeom =
    "1300000000.000 16777343 6665 position2d 00 004 001 +00.000 +00.000 +0.000 +00.440 "
    "+00.380\n";
const std::string kRangerSonarGeom =
    "1300000000.000 16777343 6665 ranger 00 004 001 +00.000 +00.000 +00.000 +00.000 +00.000 "
    "+00.000 +00.000 +00.000 +00.000 0004 +00.069 +00.136 +00.000 +00.000 +00.000 +01.571 "
    "+00.114 +00.119 +00.000 +00.000 +00.000 +00.873 +00.148 +00.078 +00.000 +00.000 +00.000 "
    "+00.524 +00.166 +00.027 +00.000 +00.000 +00.000 +00.175 0004 +00.010 +00.010 +00.010 "
    "+00.010 +00.010 +00.010 +00.010 +00.010 +00.010 +00.010 +00.010 +00.010 \n";
const std::string kSonarConfig =
    "1300000000.000 16777343 6665 ranger 00 004 005 -0.130900 0.130900 0.261800 0.000000 "
    "5.000000 0.020000 10.000000 \n";
const std::string kLaserGeom =
    "1300000000.000 16777343 6665 ranger 01 004 001 +00.030 +00.000 +00.000 +00.000 +00.000 "
    "+00.000 +00.156 +00.155 +00.190 0001 +00.000 +00.000 +00.000 +00.000 +00.000 +00.000 0001 "
    "+00.156 +00.155 +00.190 \n";
const std::string kLaserConfig =
    "1300000000.000 16777343 6665 ranger 01 004 005 -1.570796 1.570796 0.785398 0.000000 "
    "8.000000 0.020000 10.000000 \n";

std::string ranger_position(const std::string& t, const std::string& x) {
  return t + " 16777343 6665 position2d 00 001 001 " + x +
         " +00.000 +0.000 +00.500 +00.000 +00.000 0\n";
}
// A ranger's data line: subtype 001 ranges, 003 intensities.
std::string ranger(const std::string& t, const std::string& index, const std::string& subtype,
                   const std::string& payload) {
  return t + " 16777343 6665 ranger " + index + " 001 " + subtype + " " + payload + " \n";
}
// One Stage cycle: the position, then each ranger's ranges and intensities.
std::string cycle(const std::string& t, const std::string& x, const std::string& sonar) {
  return ranger_position(t, x) + ranger(t, "00", "001", sonar) +
         ranger(t, "00", "003", "0004 1.000 1.000 0.000 0.000") +
         ranger(t, "01", "001", "0005 1.000 1.100 1.200 1.300 1.400") +
         ranger(t, "01", "003", "0005 1.000 1.000 1.000 1.000 1.000");
}

TEST(PlayerRanger, Stage4SonarRingIsReadLaserSkipped) {
  const fs::path p = ranger_log(
      "stage.log", kRangerHeader + kRangerPositionGeom + kRangerSonarGeom + kSonarConfig +
                       kLaserGeom + kLaserConfig +
                       cycle("1300000000.100", "+00.000", "0004 1.500 2.250 5.000 0.000") +
                       cycle("1300000000.200", "+00.050", "0004 1.400 2.200 4.100 0.000"));
  EXPECT_EQ(detect_log_format(p), LogFormat::kPlayer);
  const ImportedLog log = import_player_log(p);
  ASSERT_EQ(log.geometry.sonars.size(), 4u);  // one mount per element pose, not the P2-AT's 16
  EXPECT_EQ(log.geometry.sonars[0].x_m, 0.069);
  EXPECT_EQ(log.geometry.sonars[0].y_m, 0.136);
  EXPECT_EQ(log.geometry.sonars[0].heading_rad, 1.571);
  EXPECT_EQ(log.geometry.sonars[3].heading_rad, 0.175);
  EXPECT_EQ(log.geometry.sonar_max_range_m, 5.0);        // the config's max_range
  EXPECT_EQ(log.geometry.sonar_beam_width_rad, 0.2618);  // max_angle - min_angle
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].time_s, 0.1);  // from the first line read, the geometry at .000
  ASSERT_EQ(log.frames[0].sonar.size(), 4u);
  EXPECT_EQ(log.frames[0].sonar[0].range_m, 1.5);
  EXPECT_TRUE(log.frames[0].sonar[1].echo);
  EXPECT_FALSE(log.frames[0].sonar[2].echo);  // 5.000: the max range, nothing heard
  EXPECT_FALSE(log.frames[0].sonar[3].echo);  // 0.000
  EXPECT_EQ(log.frames[0].sonar[3].index, 3);
  EXPECT_EQ(log.frames[1].odometry.x_m, 0.05);  // paired with the position before it
  EXPECT_EQ(log.frames[1].sonar[2].range_m, 4.1);
  // position2d geometry; sonar intensities x2; the laser's geometry, config, 2 x 2 data lines.
  EXPECT_EQ(log.ignored_lines, 9u);
}

// Element poses are relative to the device (Stage: to the ranger model on the robot): a ring
// mounted 0.1 m ahead and turned a quarter left has its mounts moved and turned so.
TEST(PlayerRanger, ElementPosesComposeOntoTheDevicePose) {
  const std::string geom =
      "1300000000.000 16777343 6665 ranger 00 004 001 +00.100 +00.000 +00.000 +00.000 +00.000 "
      "+01.571 +00.000 +00.000 +00.000 0002 +00.200 +00.000 +00.000 +00.000 +00.000 +00.000 "
      "+00.000 +00.100 +00.000 +00.000 +00.000 +01.571 0000 \n";
  const ImportedLog log = import_player_log(
      ranger_log("p.log", kRangerHeader + geom + ranger_position("1300000000.100", "+00.000") +
                              ranger("1300000000.100", "00", "001", "0002 1.000 2.000")));
  ASSERT_EQ(log.geometry.sonars.size(), 2u);
  EXPECT_NEAR(log.geometry.sonars[0].x_m, 0.1, 1e-3);
  EXPECT_NEAR(log.geometry.sonars[0].y_m, 0.2, 1e-3);
  EXPECT_NEAR(log.geometry.sonars[0].heading_rad, 1.571, 1e-9);
  EXPECT_NEAR(log.geometry.sonars[1].x_m, 0.0, 1e-3);
  EXPECT_NEAR(log.geometry.sonars[1].heading_rad, 3.142 - 2 * 3.141592653589793, 1e-9);
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].sonar.size(), 2u);
}

// Ranges with a geometry in the line (1:2, PLAYER_RANGER_DATA_RANGESTAMPED): writelog writes
// have_geom, the geometry, then the config's seven numbers without a have_config flag.
TEST(PlayerRanger, StampedRangesCarryTheirGeometry) {
  const std::string stamped =
      "0002 1.500 2.250 1 +00.000 +00.000 +00.000 +00.000 +00.000 +00.000 +00.000 +00.000 "
      "+00.000 0002 +00.069 +00.136 +00.000 +00.000 +00.000 +01.571 +00.114 +00.119 +00.000 "
      "+00.000 +00.000 +00.873 0002 +00.010 +00.010 +00.010 +00.010 +00.010 +00.010 -0.1309 "
      "0.1309 0.2618 0.0000 5.0000 0.0200 10.0000";
  const ImportedLog log = import_player_log(
      ranger_log("p.log", kRangerHeader + ranger_position("1300000000.100", "+00.000") +
                              ranger("1300000000.100", "00", "002", stamped) +
                              ranger("1300000000.200", "00", "002", "0001 0.750 0")));
  ASSERT_EQ(log.geometry.sonars.size(), 2u);
  EXPECT_EQ(log.geometry.sonars[1].heading_rad, 0.873);
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].sonar[1].range_m, 2.25);
  EXPECT_EQ(log.frames[1].sonar.at(0).range_m, 0.75);
}

// A config a driver left zero (Player's sonartoranger sends "a pile of zeroes") says nothing:
// the P2-AT's range and beam stay.
TEST(PlayerRanger, ZeroConfigKeepsTheDefaults) {
  const std::string zeros =
      "1300000000.000 16777343 6665 ranger 00 004 005 0.000000 0.000000 0.000000 0.000000 "
      "0.000000 0.000000 0.000000 \n";
  const ImportedLog log = import_player_log(
      ranger_log("p.log", kRangerHeader + kRangerSonarGeom + zeros +
                              ranger_position("1300000000.100", "+00.000") +
                              ranger("1300000000.100", "00", "001", "0004 1.0 1.0 1.0 1.0")));
  EXPECT_EQ(log.geometry.sonar_max_range_m, mapper::p2at_geometry().sonar_max_range_m);
  EXPECT_EQ(log.geometry.sonar_beam_width_rad, mapper::p2at_geometry().sonar_beam_width_rad);
}

// Without a geometry a ranger's ranges could be a laser's as well as a ring's, and cannot be
// placed: alone, an error naming its first ranges line; beside a sonar array, skipped.
TEST(PlayerRanger, RangerWithoutGeometry) {
  const std::string lines = ranger_position("1300000000.100", "+00.000") +
                            ranger("1300000000.100", "00", "001", "0004 1.500 2.250 5.000 0.000");
  EXPECT_EQ(ranger_error_of(ranger_log("p.log", kRangerHeader + lines)),
            "p.log:10: 6665:ranger:0 logs ranges (4 a line at most) but never its geometry (the "
            "reply to GET_GEOM, type 4 subtype 1, which writelog writes first): without one pose "
            "per element it cannot be told from a laser, nor its readings placed");
  const std::string sonar = "1300000000.100 16777343 6665 sonar 00 001 001 0002 +1.000 +2.000 \n";
  const ImportedLog log = import_player_log(ranger_log("q.log", kRangerHeader + lines + sonar));
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].sonar.size(), 2u);
  EXPECT_EQ(log.ignored_lines, 1u);
}

// A Player 3 log of odometry and a laser ranger maps nothing: the error says so, and why the
// ranger was not read.
TEST(PlayerRanger, LaserOnlyLogSaysWhatItHolds) {
  const std::string text = kRangerHeader + kRangerPositionGeom + kLaserGeom + kLaserConfig +
                           ranger_position("1300000000.100", "+00.000") +
                           ranger("1300000000.100", "01", "001", "0003 1.000 1.100 1.200");
  EXPECT_EQ(ranger_error_of(ranger_log("p.log", text)),
            "p.log: no sonar readings (sonar ranges, or ranges of a ranger with one pose per "
            "element); lines: 6665:position2d:0 (1 read, 1 skipped), 6665:ranger:1 (3 skipped: one "
            "element pose, up to 3 ranges a line: a laser, not a sonar ring)");
}

// Before: 8 mounts and every echo twice. A Player 3 log can hold p2os's sonar:0 and a
// sonartoranger ranger:0 of the same ring (one pose per element, so taken for sonar), and both
// were joined. The robot's sonar is read; its rangers only when it has no sonar with readings.
const std::string kP2osSonarGeom =
    "1300000000.000 16777343 6665 sonar 00 004 001 4 +00.069 +00.136 +1.5710 +00.114 +00.119 "
    "+0.8730 +00.148 +00.078 +0.5240 +00.166 +00.027 +0.1750 \n";

TEST(PlayerRanger, RangerBesideSonarIsTheSameRing) {
  const std::string text =
      kRangerHeader + kRangerPositionGeom + kP2osSonarGeom + kRangerSonarGeom + kSonarConfig +
      ranger_position("1300000000.100", "+00.000") +
      "1300000000.100 16777343 6665 sonar 00 001 001 4 1.500 2.250 5.000 0.000 \n" +
      ranger("1300000000.100", "00", "001", "0004 1.500 2.250 5.000 0.000");
  const ImportedLog log = import_player_log(ranger_log("p.log", text));
  ASSERT_EQ(log.geometry.sonars.size(), 4u);
  EXPECT_EQ(log.geometry.sonars[1].heading_rad, 0.873);
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].sonar.size(), 4u);
  EXPECT_EQ(log.ignored_lines, 4u);  // position2d geometry; the ranger's geometry, config, ranges
  // A sonar whose ranges lines hold no range (count 0) is no sonar read: the ranger beside it
  // is the ring (before, the sonar "was read" and the log had no readings at all).
  const std::string empty = kRangerHeader + kRangerPositionGeom + kP2osSonarGeom +
                            kRangerSonarGeom + kSonarConfig +
                            ranger_position("1300000000.100", "+00.000") +
                            "1300000000.100 16777343 6665 sonar 00 001 001 0 \n" +
                            ranger("1300000000.100", "00", "001", "0004 1.500 2.250 5.000 0.000");
  const ImportedLog ranger_read = import_player_log(ranger_log("q.log", empty));
  ASSERT_EQ(ranger_read.frames.size(), 1u);
  EXPECT_EQ(ranger_read.frames[0].sonar.size(), 4u);
  EXPECT_EQ(ranger_read.ignored_lines, 3u);  // position2d geometry; sonar geometry, empty ranges
  // Only empty sonar lines: each is skipped for what it is.
  const std::string only_empty = kRangerHeader + kRangerPositionGeom + kP2osSonarGeom +
                                 ranger_position("1300000000.100", "+00.000") +
                                 "1300000000.100 16777343 6665 sonar 00 001 001 0 \n";
  EXPECT_EQ(ranger_error_of(ranger_log("e.log", only_empty)),
            "e.log: no sonar readings (sonar ranges, or ranges of a ranger with one pose per "
            "element); lines: 6665:position2d:0 (1 read, 1 skipped), 6665:sonar:0 (2 skipped: "
            "no ranges)");
}

// Before: "6666:ranger:0 (2 skipped)", with no reason.
TEST(PlayerRanger, AnotherRobotsRangerSaysWhose) {
  std::string geometry = kRangerSonarGeom;
  geometry.replace(geometry.find(" 6665 "), 6, " 6666 ");
  const std::string text =
      kRangerHeader + kRangerPositionGeom + geometry +
      ranger_position("1300000000.100", "+00.000") +
      "1300000000.100 16777343 6666 ranger 00 001 001 0004 1.500 2.250 5.000 0.000 \n";
  EXPECT_EQ(ranger_error_of(ranger_log("p.log", text)),
            "p.log: no sonar readings (sonar ranges, or ranges of a ranger with one pose per "
            "element); lines: 6665:position2d:0 (1 read, 1 skipped), 6666:ranger:0 (2 skipped: "
            "another robot's (the odometry is 6665's))");
}

// A geometry of `poses` element poses at the device origin, their sizes left out.
std::string ring_geometry(int poses) {
  std::string line =
      "1300000000.000 16777343 6665 ranger 00 004 001 0 0 0 0 0 0 0 0 0 " + std::to_string(poses);
  for (int i = 0; i < poses; ++i) line += " 0 0 0 0 0 " + std::to_string(i % 6);
  return line + " 0000 \n";
}

// Before: a ranger of 256 element poses imported as 256 transducers, and write_cogmap_log of
// the import wrote a log its own reader refused ("expected sonars=N (integer 0..255)"): found
// by foreign_log_fuzz, which reads back what it imports.
TEST(PlayerRanger, MoreThan255ElementPosesAreRefused) {
  const std::string data = ranger_position("1300000000.100", "+00.000") +
                           ranger("1300000000.100", "00", "001", "0002 1.000 2.000");
  EXPECT_EQ(ranger_error_of(ranger_log("p.log", kRangerHeader + ring_geometry(256) + data)),
            "p.log:9: the geometry of 6665:ranger:0 has 256 poses, 256 sonar transducers in all: "
            "cogmap reads at most 255 (as many as a cogmap log holds)");
  const ImportedLog log =
      import_player_log(ranger_log("q.log", kRangerHeader + ring_geometry(255) + data));
  EXPECT_EQ(log.geometry.sonars.size(), 255u);
  const fs::path exported = ranger_log("q.cogmap.log", "");
  write_cogmap_log(exported, log);
  EXPECT_EQ(LogReader(exported).geometry().sonars.size(), 255u);
}

// Counts beyond any ranger (2^31, 2^64) and numbers that are not finite doubles are refused on
// their own field, before anything is sized by them (was and is).
TEST(PlayerRanger, HugeCountsAndNonFiniteNumbersNameTheirField) {
  EXPECT_EQ(ranger_error_of(ranger_log("c.log", kRangerHeader + ranger("1300000000.1", "00", "001",
                                                                       "2147483648 1.0 1.0"))),
            "c.log:9: expected ranges_count (0..65535) at field 8, got '2147483648'");
  EXPECT_EQ(ranger_error_of(ranger_log(
                "g.log", kRangerHeader + "1300000000.000 16777343 6665 ranger 00 004 001 "
                                         "0 0 0 0 0 0 0 0 0 18446744073709551616 0\n")),
            "g.log:9: expected ranger element_poses_count (0..65535) at field 17, got "
            "'18446744073709551616'");
  for (const std::string v : {"nan", "inf", "-1e400"}) {
    EXPECT_EQ(
        ranger_error_of(ranger_log("r.log", kRangerHeader + kRangerSonarGeom +
                                                ranger_position("1300000000.1", "+0") +
                                                ranger("1300000000.1", "00", "001", "0001 " + v))),
        "r.log:11: expected range at field 9, got '" + v + "'");
    EXPECT_EQ(ranger_error_of(ranger_log(
                  "k.log", kRangerHeader + kRangerSonarGeom + ranger_position("1300000000.1", v))),
              "k.log:10: expected px at field 8, got '" + v + "'");
  }
}

// Lines of the types read stay strict: the file, the line and the field.
TEST(PlayerRanger, MalformedLinesNameFileAndLine) {
  // A geometry cut short (the log cut mid-line): 4 element poses announced, 1 written.
  const std::string cut =
      "1300000000.000 16777343 6665 ranger 00 004 001 +00.000 +00.000 +00.000 +00.000 +00.000 "
      "+00.000 +00.000 +00.000 +00.000 0004 +00.069 +00.136 +00.000 +00.000 +00.000 +01.571\n";
  EXPECT_EQ(ranger_error_of(ranger_log("g.log", kRangerHeader + cut)),
            "g.log:9: expected ranger geometry: 4 element poses (px py pz proll ppitch pyaw) then "
            "element_sizes_count at field 24, got 'end of line'");
  const std::string typo =
      "1300000000.000 16777343 6665 ranger 00 004 001 +00.000 +00.000 +00.000 +00.000 +00.000 "
      "+00.000 +00.000 +00.000 +00.000 0001 +00.069 +00.l36 +00.000 +00.000 +00.000 +01.571 "
      "0000 \n";
  EXPECT_EQ(ranger_error_of(ranger_log("t.log", kRangerHeader + typo)),
            "t.log:9: expected ranger element pose (px py pz proll ppitch pyaw) at field 19, got "
            "'+00.l36'");
  // More ranges than the geometry has elements.
  EXPECT_EQ(ranger_error_of(ranger_log(
                "r.log", kRangerHeader + kRangerSonarGeom + ranger_position("1300000000.1", "+0") +
                             ranger("1300000000.1", "00", "001", "0005 1.0 1.0 1.0 1.0 1.0"))),
            "r.log:11: expected at most 4 ranges (one per element pose of the geometry at line 9) "
            "at field 8, got '0005'");
  EXPECT_EQ(ranger_error_of(ranger_log(
                "c.log", kRangerHeader + kRangerSonarGeom + ranger_position("1300000000.1", "+0") +
                             ranger("1300000000.1", "00", "001", "0004 1.0 1.0"))),
            "c.log:11: expected ranger ranges_count range*ranges_count at field 11, got 'end of "
            "line'");
}

}  // namespace
}  // namespace cogmap::hw
