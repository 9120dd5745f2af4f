// The Player importer against files as Player 2.x/3.x's writelog driver writes them
// (server/drivers/shell/writelog.cc): its header, geometry replies first, "%014.3f %u %u %s %02u
// %03u %03u " before each payload, trailing spaces, header-only lines for messages it cannot
// log, several devices of one interface, and Player 1.x files named as such. Exact text.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cogmap/hw/log_import.h"
#include "import_test_files.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;

fs::path player_log(const std::string& name, const std::string& text) {
  return testing::write_log("player_import_test", name, text);
}

std::string player_error_of(const fs::path& p) {
  return testing::import_error([](const fs::path& f) { return import_player_log(f); }, p);
}

// WriteLog::OpenFile (Player 2.1).
const std::string kPlayerHeader = testing::writelog_header("2.1.3");

// Geometry replies (type 4 = RESP_ACK): sonar "%u " then "%+07.3f %+07.3f %+07.4f " per pose;
// position2d "%+07.3f %+07.3f %+04.3f %+07.3f %+07.3f" (pose, length, width).
const std::string kPlayerSonarGeom =
    "1199999999.990 16777343 6665 sonar 00 004 001 2 +00.147 +00.136 +1.5708 +00.193 +00.119 "
    "+0.8727 \n";
const std::string kPlayerPositionGeom =
    "1199999999.990 16777343 6665 position2d 00 004 001 +00.000 +00.000 +0.000 +00.626 "
    "+00.505\n";

std::string player_position(const std::string& t, const std::string& index, const std::string& x,
                            int stall = 0, const std::string& robot = "6665") {
  return t + " 16777343 " + robot + " position2d " + index + " 001 001 " + x +
         " +00.000 +0.000 +00.500 +00.000 +00.000 " + std::to_string(stall) + "\n";
}
std::string ranges(const std::string& t, const std::string& index, const std::string& values,
                   const std::string& robot = "6665") {
  return t + " 16777343 " + robot + " sonar " + index + " 001 001 " + values + " \n";
}

// A file as writelog writes it: was read, and still is; times are exact decimals now.
TEST(PlayerImport, WritelogFileAsPlayer2Writes) {
  const std::string text =
      kPlayerHeader + kPlayerSonarGeom + kPlayerPositionGeom +
      "1199999999.990 16777343 6665 laser 00 004 001 +0.000 +0.000   0.000   0.000   0.000\n" +
      player_position("1200000000.000", "00", "+00.000") +
      ranges("1200000000.000", "00", "2 1.500 5.000") +
      "1200000000.050 16777343 6665 laser 00 001 001 0001 -1.5708 +1.5708 +0.01745329 +08.0000 "
      "0002 1.000  0 1.100  0 \n"
      "1200000000.060 16777343 6665 sonar 00 001 003 \n" +  // a message writelog cannot log
      player_position("1200000000.100", "00", "+00.050", 1) +
      ranges("1200000000.100", "00", "2 0.750 2.000");
  const fs::path p = player_log("w.log", text);
  EXPECT_EQ(detect_log_format(p), LogFormat::kPlayer);
  const ImportedLog log = import_player_log(p);
  ASSERT_EQ(log.geometry.sonars.size(), 2u);
  EXPECT_EQ(log.geometry.sonars[1].heading_rad, 0.8727);
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].time_s, 0.01);  // from the first line read, the geometry at .990
  EXPECT_EQ(log.frames[1].time_s, 0.11);
  EXPECT_EQ(log.frames[1].odometry.x_m, 0.05);
  EXPECT_TRUE(log.frames[1].stall_left);
  EXPECT_FALSE(log.frames[0].sonar[1].echo);  // 5.000: p2os's no echo
  EXPECT_EQ(log.frames[1].sonar[0].range_m, 0.75);
  EXPECT_EQ(log.ignored_lines, 4u);  // laser geometry, laser scan, sonar 1:3, position geometry
}

// Before: "odometry jumps 11.1803 m in 0 s": position2d:1 (a localiser, vfh or nd wrapping the
// base) was taken as odometry in turns with position2d:0. The base's device, the lowest index,
// is the odometry; the others are skipped.
TEST(PlayerImport, LowestPositionDeviceIsOdometry) {
  const std::string text = kPlayerHeader + kPlayerSonarGeom +
                           player_position("1200000000.000", "01", "+10.000") +
                           player_position("1200000000.000", "00", "+00.000") +
                           ranges("1200000000.000", "00", "2 1.5 1.6") +
                           player_position("1200000000.100", "01", "+10.050") +
                           player_position("1200000000.100", "00", "+00.050") +
                           ranges("1200000000.100", "00", "2 1.4 1.5");
  const ImportedLog log = import_player_log(player_log("p.log", text));
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].odometry.x_m, 0.0);
  EXPECT_EQ(log.frames[1].odometry.x_m, 0.05);
  EXPECT_EQ(log.ignored_lines, 2u);
}

// Before: "expected at most 1 ranges at field 8, got '2'": sonar:1's geometry replaced
// sonar:0's. Two arrays of one robot (rflex's two banks) are one set of mounts, sonar:0's
// first; sonar:1's readings are numbered after them.
TEST(PlayerImport, TwoSonarArraysAreJoined) {
  const std::string text =
      kPlayerHeader + kPlayerSonarGeom +
      "1199999999.990 16777343 6665 sonar 01 004 001 1 -00.200 +00.000 +3.1416 \n" +
      player_position("1200000000.000", "00", "+00.000") +
      ranges("1200000000.000", "00", "2 1.5 1.6") + ranges("1200000000.000", "01", "1 0.8");
  const ImportedLog log = import_player_log(player_log("p.log", text));
  ASSERT_EQ(log.geometry.sonars.size(), 3u);
  EXPECT_EQ(log.geometry.sonars[2].x_m, -0.2);
  ASSERT_EQ(log.frames.size(), 2u);
  ASSERT_EQ(log.frames[1].sonar.size(), 1u);
  EXPECT_EQ(log.frames[1].sonar[0].index, 2);
  EXPECT_EQ(log.frames[1].sonar[0].range_m, 0.8);
}

// Before: two arrays of 200 and 56 were joined into 256 transducers, more than a cogmap log
// holds (write_cogmap_log of the import wrote a log its reader refused).
TEST(PlayerImport, JoinedArraysOfMoreThan255AreRefused) {
  const auto geometry = [](const std::string& index, int poses) {
    std::string line =
        "1199999999.990 16777343 6665 sonar " + index + " 004 001 " + std::to_string(poses);
    for (int i = 0; i < poses; ++i) line += " +00.100 +00.000 +0.0000";
    return line + " \n";
  };
  const std::string data = player_position("1200000000.000", "00", "+00.000") +
                           ranges("1200000000.000", "00", "1 1.5") +
                           ranges("1200000000.000", "01", "1 0.8");
  EXPECT_EQ(player_error_of(player_log(
                "p.log", kPlayerHeader + geometry("00", 200) + geometry("01", 56) + data)),
            "p.log:10: the geometry of 6665:sonar:1 has 56 poses, 256 sonar transducers in all: "
            "cogmap reads at most 255 (as many as a cogmap log holds)");
  const ImportedLog log = import_player_log(
      player_log("q.log", kPlayerHeader + geometry("00", 200) + geometry("01", 55) + data));
  EXPECT_EQ(log.geometry.sonars.size(), 255u);
}

// A second array with no geometry cannot be placed: it is skipped, not read with wrong mounts.
TEST(PlayerImport, SonarArrayWithoutGeometryBesideOneWithIsSkipped) {
  const std::string text =
      kPlayerHeader + kPlayerSonarGeom + player_position("1200000000.000", "00", "+00.000") +
      ranges("1200000000.000", "01", "3 0.8 0.9 1.0") + ranges("1200000000.000", "00", "2 1.5 1.6");
  const ImportedLog log = import_player_log(player_log("p.log", text));
  EXPECT_EQ(log.geometry.sonars.size(), 2u);
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].sonar.size(), 2u);
  EXPECT_EQ(log.ignored_lines, 1u);
}

// One array at index 1 (was and is read), with the P2-AT's mounts when it has no geometry.
TEST(PlayerImport, SingleSonarAtIndexOne) {
  const std::string text = kPlayerHeader + player_position("1200000000.000", "00", "+00.000") +
                           ranges("1200000000.000", "01", "16 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1");
  const ImportedLog log = import_player_log(player_log("p.log", text));
  EXPECT_EQ(log.geometry.sonars.size(), 16u);
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].sonar.size(), 16u);
}

// Lines of a second robot (Stage serving robots on ports 6665 and 6666) are skipped: before,
// its poses were mixed with the first robot's.
TEST(PlayerImport, SecondRobotIsSkipped) {
  const std::string text = kPlayerHeader + kPlayerSonarGeom +
                           player_position("1200000000.000", "00", "+05.000", 0, "6666") +
                           player_position("1200000000.000", "00", "+00.000") +
                           ranges("1200000000.000", "00", "2 1.5 1.6") +
                           ranges("1200000000.000", "00", "2 0.1 0.2", "6666");
  const ImportedLog log = import_player_log(player_log("p.log", text));
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].sonar[0].range_m, 1.5);
  EXPECT_EQ(log.ignored_lines, 2u);
}

// A used array's mounts cannot change halfway: every earlier frame would be re-read with them.
TEST(PlayerImport, GeometryThatChangesIsRefused) {
  const std::string text =
      kPlayerHeader + kPlayerSonarGeom + player_position("1200000000.000", "00", "+00.000") +
      ranges("1200000000.000", "00", "2 1.5 1.6") +
      "1200000000.050 16777343 6665 sonar 00 001 002 1 +00.100 +00.000 +0.0000 \n";
  EXPECT_EQ(player_error_of(player_log("p.log", text)),
            "p.log:12: the geometry of 6665:sonar:0 differs from the one at line 9: an array's "
            "mounts cannot change within a log");
  // The same mounts again (a driver publishing its geometry as data) are fine.
  const std::string same = kPlayerHeader + kPlayerSonarGeom +
                           player_position("1200000000.000", "00", "+00.000") +
                           "1200000000.050 16777343 6665 sonar 00 001 002 2 +00.147 +00.136 "
                           "+1.5708 +00.193 +00.119 +0.8727 \n" +
                           ranges("1200000000.050", "00", "2 1.5 1.6");
  EXPECT_EQ(player_error_of(player_log("q.log", same)), "");
}

// p2os reports stall as 0 or 1; the payload field is a uint8_t, so any non-zero is a stall.
TEST(PlayerImport, StallIsAnyNonZero) {
  const ImportedLog log = import_player_log(
      player_log("p.log", kPlayerHeader + player_position("1200000000.000", "00", "+00.000", 3) +
                              ranges("1200000000.000", "00", "1 1.5")));
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_TRUE(log.frames[0].stall_left);
  EXPECT_NE(player_error_of(player_log("q.log", kPlayerHeader + player_position("1200000000.000",
                                                                                "00", "+0", 256)))
                .find("q.log:9: expected stall"),
            std::string::npos);
}

// Player 1.x wrote "time host port interface index data_time data..." with no type or subtype,
// and called odometry `position`. Before: "expected time host robot interface index type
// subtype at field 7", or with a sonar line "expected message type (0..255)"; without the
// header, "expected a cogmap, CARMEN or Player log line".
TEST(PlayerImport, Player1LogIsNamed) {
  const std::string lines =
      "1100000000.000 myhost 6665 position 00 1100000000.000 +00.000 +00.000 +0.000 +00.000 "
      "+00.000 +0.000 0\n"
      "1100000000.100 myhost 6665 sync 00 1100000000.100 \n";
  const fs::path with =
      player_log("p1.log", "## Player version 1.6.5 \n## File version 0.1.0 \n" + lines);
  EXPECT_EQ(player_error_of(with),
            "p1.log:2: a Player 1.x log (file version 0.1.0): cogmap reads the files of Player "
            "2.x and 3.x's writelog (file version 0.3.0), whose lines have type and subtype "
            "fields");
  const fs::path without = player_log("p1n.log", lines);
  EXPECT_EQ(detect_log_format(without), LogFormat::kPlayer);
  EXPECT_EQ(player_error_of(without),
            "p1n.log:1: interface 'position' is Player 1.x's: cogmap reads the files of Player "
            "2.x and 3.x's writelog (position2d and sonar)");
}

// Files cut from a longer log lose the header; any writelog line still says Player.
TEST(PlayerImport, DetectedWithoutHeader) {
  EXPECT_EQ(detect_log_format(
                player_log("p.log", "1200000000.000 16777343 6665 ranger 00 001 001 1 1.0 \n" +
                                        player_position("1200000000.000", "00", "+00.000"))),
            LogFormat::kPlayer);
  EXPECT_EQ(
      detect_log_format(player_log("q.log", "1200000000.000 16777343 6665 localize 00 001 001\n")),
      LogFormat::kPlayer);
}

// Before: odometry and a laser imported with exit 0 into frames without one reading (only
// ignored_lines hinted at it), and the replay mapped nothing. Now an error saying what the log
// holds, in the words of the ROS bag importer's "no sonar topic (...); topics: ...".
TEST(PlayerImport, LogWithoutSonarSaysWhatItHolds) {
  const std::string laser =
      " 16777343 6665 laser 00 001 001 0001 -1.5708 +1.5708 +0.01745329 +08.0000 0002 1.000  0 "
      "1.100  0 \n";
  const std::string text = kPlayerHeader + kPlayerPositionGeom +
                           player_position("1200000000.000", "00", "+00.000") + "1200000000.000" +
                           laser + player_position("1200000000.100", "00", "+00.050") +
                           "1200000000.100" + laser;
  EXPECT_EQ(player_error_of(player_log("p.log", text)),
            "p.log: no sonar readings (sonar ranges, or ranges of a ranger with one pose per "
            "element); lines: 6665:position2d:0 (2 read, 1 skipped), 6665:laser:0 (2 skipped)");
  // Sonar lines of another robot only: still none of this robot's.
  const std::string other = kPlayerHeader + player_position("1200000000.000", "00", "+00.000") +
                            ranges("1200000000.000", "00", "2 1.5 1.6", "6666");
  EXPECT_EQ(player_error_of(player_log("q.log", other)),
            "q.log: no sonar readings (sonar ranges, or ranges of a ranger with one pose per "
            "element); lines: 6665:position2d:0 (1 read), 6666:sonar:0 (1 skipped: another "
            "robot's (the odometry is 6665's))");
}

// Before: "6666:position2d:0 (1 skipped), 6665:sonar:0 (1 skipped)", the lines of another robot
// listed with no reason. Another port, or the same port on another host (named then).
TEST(PlayerImport, AnotherRobotsLinesSayWhose) {
  const std::string other_host = "1200000000.000 16777344 6665 sonar 00 001 001 2 1.500 1.600 \n";
  const std::string text = kPlayerHeader +
                           player_position("1200000000.000", "00", "+05.000", 0, "6666") +
                           player_position("1200000000.000", "00", "+00.000") + other_host;
  EXPECT_EQ(player_error_of(player_log("p.log", text)),
            "p.log: no sonar readings (sonar ranges, or ranges of a ranger with one pose per "
            "element); lines: 6666:position2d:0 (1 skipped: another robot's (the odometry is "
            "6665's)), 6665:position2d:0 (1 read), 6665:sonar:0 (1 skipped: another robot's (the "
            "odometry is 16777343:6665's))");
}

// Lines of the types read stay strict: the file, the line and the field.
TEST(PlayerImport, MalformedLinesNameFileAndLine) {
  EXPECT_EQ(player_error_of(
                player_log("p.log", kPlayerHeader + ranges("1200000000.000", "00", "3 1.5 1.6"))),
            "p.log:9: expected sonar count range*count at field 11, got 'end of line'");
  EXPECT_EQ(player_error_of(player_log("q.log", kPlayerHeader +
                                                    "1200000000.000 16777343 6665 position2d 00 "
                                                    "001 001 +00.000 +00.000 +0.000 0\n")),
            "q.log:9: expected position2d data px py pa vx vy va stall at field 12, got 'end of "
            "line'");
}

}  // namespace
}  // namespace cogmap::hw
