// The CARMEN importer against logs as CARMEN's own logger writes them (writelog.c, readlog.c):
// SONAR without a robot pose, every other message interleaved and skipped, the logger's header,
// CRLF, trailing spaces, C's number forms, epoch timestamps to the microsecond, long PARAM
// blocks. Each case is exact synthetic text.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>
#include <utility>

#include "cogmap/hw/log_import.h"
#include "import_test_files.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;

fs::path carmen_log(const std::string& name, const std::string& text) {
  return testing::write_log("carmen_import_test", name, text);
}

std::string carmen_error_of(const fs::path& p) {
  return testing::import_error([](const fs::path& f) { return import_carmen_log(f); }, p);
}

// The header CARMEN's logger writes (carmen_logwrite_write_header), shortened.
const std::string kLoggerHeader =
    "# CARMEN Logfile\n"
    "# file format is one message per line\n"
    "# message_name [message contents] ipc_timestamp ipc_hostname logger_timestamp\n"
    "# message formats defined: PARAM SYNC ODOM RAWLASER1 RAWLASER2 RAWLASER3 RAWLASER4 "
    "ROBOTLASER1 ROBOTLASER2 FLASER RLASER LASER3 LASER4\n"
    "# ODOM x y theta tv rv accel\n"
    "# SONAR cone_angle num_sonars [sonar_reading] [sonar_offsets x y theta]\n";

// carmen_logwrite_write_base_sonar: "SONAR %f %d ", "%.2lf " per range, "%.3f %.3f %f " per
// offset, then "%lf %s %lf\n" (timestamp, host, logger timestamp). No robot pose.
const std::string kSonar1 =
    "SONAR 0.261799 3 1.50 2.25 5.00 0.147 0.136 1.570796 0.193 0.119 0.872665 "
    "0.227 0.079 0.523599 1100000000.050000 p2at 0.051234\n";
const std::string kSonar2 =
    "SONAR 0.261799 3 1.40 0.00 3.10 0.147 0.136 1.570796 0.193 0.119 0.872665 "
    "0.227 0.079 0.523599 1100000000.150000 p2at 0.151234\n";
// carmen_logwrite_write_odometry: "ODOM %f %f %f %f %f %f %f %s %f\n".
const std::string kOdom1 =
    "ODOM 0.000000 0.000000 0.000000 0.000000 0.000000 0.000000 1100000000.000000 p2at 0.001234\n";
const std::string kOdom2 =
    "ODOM 0.050000 0.000000 0.010000 0.500000 0.100000 0.000000 1100000000.100000 p2at 0.101234\n";

// Before: refused, "expected SONAR cone n range*n (x y theta)*n x y theta [tv rv] timestamp host
// logger_ts at field 12": the importer wanted a robot pose CARMEN never writes.
TEST(CarmenImport, SonarLineAsCarmenWritesIt) {
  const fs::path p = carmen_log("real.log", kLoggerHeader + kOdom1 + kSonar1 + kOdom2 + kSonar2);
  EXPECT_EQ(detect_log_format(p), LogFormat::kCarmen);
  const ImportedLog log = import_carmen_log(p);
  ASSERT_EQ(log.frames.size(), 4u);
  ASSERT_EQ(log.geometry.sonars.size(), 3u);
  EXPECT_EQ(log.geometry.sonars[2].x_m, 0.227);
  EXPECT_EQ(log.geometry.sonars[2].heading_rad, 0.523599);
  EXPECT_EQ(log.geometry.sonar_beam_width_rad, 0.261799);
  const auto& s1 = log.frames[1];
  EXPECT_EQ(s1.time_s, 0.05);
  EXPECT_EQ(s1.odometry.x_m, 0.0);  // the ODOM before it
  ASSERT_EQ(s1.sonar.size(), 3u);
  EXPECT_EQ(s1.sonar[0].range_m, 1.5);
  EXPECT_TRUE(s1.sonar[1].echo);
  EXPECT_FALSE(s1.sonar[2].echo);  // 5.00: the P2-AT's maximum
  const auto& s2 = log.frames[3];
  EXPECT_EQ(s2.time_s, 0.15);
  EXPECT_EQ(s2.odometry.x_m, 0.05);
  EXPECT_EQ(s2.odometry.theta_rad, 0.01);
  EXPECT_FALSE(s2.sonar[1].echo);  // 0.00: no echo
  EXPECT_EQ(s2.sonar[2].range_m, 3.1);
  EXPECT_EQ(log.ignored_lines, 0u);
}

// Before: the same refusal. A SONAR line before the first ODOM has no pose to take.
TEST(CarmenImport, SonarBeforeAnyOdomIsSkipped) {
  const ImportedLog log = import_carmen_log(carmen_log("l.log", kSonar1 + kOdom2 + kSonar2));
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_TRUE(log.frames[0].sonar.empty());
  EXPECT_EQ(log.frames[0].time_s, 0.0);  // time starts at the first line read
  EXPECT_EQ(log.frames[1].time_s, 0.05);
  EXPECT_EQ(log.frames[1].sonar.size(), 3u);
  EXPECT_EQ(log.ignored_lines, 1u);
}

// An odometry more than 0.5 s old is not the robot's pose at the sonar's time.
TEST(CarmenImport, SonarWithStaleOdomIsSkipped) {
  const std::string late =
      "SONAR 0.261799 1 1.40 0.147 0.136 1.570796 1100000000.700000 p2at 0.701234\n";
  const std::string odom = "ODOM 0.1 0 0 0 0 0 1100000000.800000 p2at 0.801234\n";
  const std::string fresh =
      "SONAR 0.261799 1 1.30 0.147 0.136 1.570796 1100000001.200000 p2at 1.201234\n";
  const ImportedLog log = import_carmen_log(carmen_log("l.log", kOdom1 + late + odom + fresh));
  ASSERT_EQ(log.frames.size(), 3u);  // two ODOM frames, the second SONAR line (0.4 s after)
  EXPECT_EQ(log.frames[2].time_s, 1.2);
  EXPECT_EQ(log.frames[2].sonar.at(0).range_m, 1.3);
  EXPECT_EQ(log.ignored_lines, 1u);
}

// Before: "expected SONAR ... at field 12". Now it says why nothing can be mapped.
TEST(CarmenImport, SonarOnlyLogSaysWhy) {
  const fs::path p = carmen_log("s.log", kLoggerHeader + kSonar1 + kSonar2);
  EXPECT_EQ(carmen_error_of(p),
            "s.log: no ODOM line before its 2 SONAR lines: a CARMEN SONAR line has no robot "
            "pose (it takes the latest ODOM's), so there is nothing to map");
}

// Before: a log of odometry and lasers imported with exit 0 into frames without one reading
// (only ignored_lines hinted at it), and the replay mapped nothing. Now an error saying what
// the log holds, in the words of the ROS bag importer's "no sonar topic (...); topics: ...".
TEST(CarmenImport, LogWithoutSonarSaysWhatItHolds) {
  const std::string flaser =
      "FLASER 3 1.00 1.10 1.20 0.05 0.00 0.01 0.05 0.00 0.01 1100000000.010000 p2at 0.01\n";
  const std::string param = "PARAM robot_front_laser_max 81.900000 1100000000.000000 p2at 0.0\n";
  EXPECT_EQ(carmen_error_of(
                carmen_log("l.log", kLoggerHeader + param + kOdom1 + flaser + kOdom2 + flaser)),
            "l.log: no sonar readings (SONAR lines with ranges); lines: PARAM (1 skipped), ODOM "
            "(2 read), FLASER (2 skipped)");
  EXPECT_EQ(carmen_error_of(carmen_log("o.log", kOdom1 + kOdom2)),
            "o.log: no sonar readings (SONAR lines with ranges); lines: ODOM (2 read)");
  // Lasers alone, no odometry: a CARMEN log all the same, not "not a CARMEN log".
  EXPECT_EQ(carmen_error_of(carmen_log("f.log", flaser + flaser)),
            "f.log: no sonar readings (SONAR lines with ranges); lines: FLASER (2 skipped)");
  // SONAR lines that cannot be placed say why.
  const std::string late =
      "SONAR 0.261799 1 1.40 0.147 0.136 1.570796 1100000000.700000 p2at 0.701234\n";
  EXPECT_EQ(carmen_error_of(carmen_log("s.log", kOdom1 + late)),
            "s.log: no sonar readings (SONAR lines with ranges); lines: ODOM (1 read), SONAR (1 "
            "skipped: more than 0.5 s after the latest ODOM)");
}

// Before: "lines: ODOM (1 read), SONAR (3 read)" for SONAR lines of num_sonars 0, which hold
// nothing to map: they are skipped, and say why.
TEST(CarmenImport, SonarLinesWithoutRangesAreSkipped) {
  const std::string none = "SONAR 0.261799 0 1100000000.050000 p2at 0.051234\n";
  EXPECT_EQ(carmen_error_of(carmen_log("z.log", kOdom1 + none + none + none)),
            "z.log: no sonar readings (SONAR lines with ranges); lines: ODOM (1 read), SONAR (3 "
            "skipped: no ranges)");
  const ImportedLog log = import_carmen_log(carmen_log("r.log", kOdom1 + none + kSonar1));
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[1].sonar.size(), 3u);
  EXPECT_EQ(log.ignored_lines, 1u);
}

// Every other message CARMEN writes is skipped and counted, wherever it comes (was and is).
TEST(CarmenImport, OtherMessagesInterleavedAreSkipped) {
  const std::string text =
      kLoggerHeader + "PARAM robot_front_laser_max 81.900000 1100000000.000000 p2at 0.000000\n" +
      "SYNC tag1 1100000000.000000 p2at 0.000100\n" + kOdom1 +
      "FLASER 3 1.00 1.10 1.20 0.05 0.00 0.01 0.05 0.00 0.01 1100000000.010000 p2at 0.01\n"
      "RLASER 2 2.00 2.10 0.05 0.00 0.01 0.05 0.00 0.01 1100000000.011000 p2at 0.011\n"
      "ROBOTLASER1 0 -1.570796 3.141593 0.017453 81.900000 0.010000 0 2 1.000 1.100 0 0.05 0 0 "
      "0 0 0 0 0 0.5 0.5 0.1 1100000000.020000 p2at 0.02\n"
      "RAWLASER1 0 -1.570796 3.141593 0.017453 81.900000 0.010000 0 2 1.000 1.100 0 "
      "1100000000.021000 p2at 0.021\n"
      "TRUEPOS 1.000000 2.000000 0.100000 0.000000 0.000000 0.000000 1100000000.030000 sim 0.03\n"
      "GLOBALPOS 1.0 2.0 0.1 0.0 0.0 0.0 1100000000.031000 p2at 0.031\n"
      "# a comment in between\n" +
      kSonar1 + "BUMPER 2 0 1 0.1 0.2 0.1 -0.2 1100000000.060000 p2at 0.06\n" + kOdom2 + kSonar2;
  const ImportedLog log = import_carmen_log(carmen_log("l.log", text));
  EXPECT_EQ(log.frames.size(), 4u);
  EXPECT_EQ(log.ignored_lines, 9u);
  EXPECT_EQ(log.frames[1].sonar.size(), 3u);
}

// Before: a log whose first message is not one of seven names was "expected a cogmap, CARMEN or
// Player log line" in --format auto, though CARMEN writes some thirty message types.
TEST(CarmenImport, DetectsLogsStartingWithAnyCarmenMessage) {
  for (const std::string first :
       {"RAWLASER1 0 -1.57 3.14 0.01 81.9 0.01 0 1 1.0 0 1100000000.0 h 0.0\n",
        "RLASER 1 2.00 0 0 0 0 0 0 1100000000.0 h 0.0\n", "ROBOTLASER2 0 0 0 0 0 0 0 0 0 0\n",
        "NMEAGGA 1 0 0 N 0 E 0 0 0 0 0 0 0 0 1100000000.0 h 0.0\n",
        "COMMENT started 1100000000.0 h 0.0\n"}) {
    EXPECT_EQ(detect_log_format(carmen_log("first.log", first + kOdom1)), LogFormat::kCarmen)
        << first;
    // The logger's own header decides, whatever follows it.
    EXPECT_EQ(detect_log_format(carmen_log("hdr.log", kLoggerHeader + first)), LogFormat::kCarmen);
  }
}

// CRLF (a log copied through Windows), trailing spaces (the writer's "%.2lf "), and C's number
// forms: 1.2e-05, -0.000, a leading '+'. Was and is read.
TEST(CarmenImport, CrlfTrailingSpacesAndNumberForms) {
  const std::string text =
      "ODOM 1.2e-05 -0.000000 -0.000 0 0 0 1100000000.000000 p2at 0.0  \r\n"
      "SONAR 0.261799 2 +1.25 2.50 0.147 0.136 1.570796 0.193 0.119 0.872665 "
      "1100000000.050000 p2at 0.05 \r\n";
  const ImportedLog log = import_carmen_log(carmen_log("l.log", text));
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].odometry.x_m, 1.2e-05);
  EXPECT_EQ(log.frames[0].odometry.theta_rad, 0.0);
  EXPECT_EQ(log.frames[1].sonar[0].range_m, 1.25);
  EXPECT_EQ(log.frames[1].sonar[1].range_m, 2.5);
}

// Before: times were differences of doubles near 1.1e9 s, 2.4e-7 s apart, so 0.05 s read as
// 0.04999995231628418 (and wrote so into an exported cogmap log). Now the decimal difference.
TEST(CarmenImport, EpochTimestampsKeepMicroseconds) {
  const std::string text =
      "ODOM 0 0 0 0 0 0 1100000000.000000 p2at 0.0\n"
      "ODOM 0 0 0 0 0 0 1100000000.000001 p2at 0.0\n"
      "ODOM 0 0 0 0 0 0 1100000000.050000 p2at 0.0\n"
      "ODOM 0 0 0 0 0 0 1100001234.567891 p2at 0.0\n"
      "ODOM 0 0 0 0 0 0 1.1000012346e9 p2at 0.0\n"
      "SONAR 0.261799 1 1.40 0.147 0.136 1.570796 1100001234.600000 p2at 0.0\n";
  const ImportedLog log = import_carmen_log(carmen_log("l.log", text));
  ASSERT_EQ(log.frames.size(), 6u);
  EXPECT_EQ(log.frames[1].time_s, 0.000001);
  EXPECT_EQ(log.frames[2].time_s, 0.05);
  EXPECT_EQ(log.frames[3].time_s, 1234.567891);
  EXPECT_EQ(log.frames[4].time_s, 1234.6);  // exponent form: read as the number it is
}

// The logger writes every parameter first: hundreds of PARAM lines before any data.
TEST(CarmenImport, LongParamBlockFirst) {
  std::string text = kLoggerHeader;
  for (int i = 0; i < 700; ++i) {
    text += "PARAM module_param" + std::to_string(i) + " value" + std::to_string(i) +
            " 1100000000.000000 p2at 0.000000\n";
  }
  const fs::path p = carmen_log("l.log", text + kOdom1 + kSonar1);
  EXPECT_EQ(detect_log_format(p), LogFormat::kCarmen);
  const ImportedLog log = import_carmen_log(p);
  EXPECT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.ignored_lines, 700u);
}

// A SONAR line that fits no layout stays an error naming the file, the line and both layouts.
TEST(CarmenImport, MalformedSonarNamesFileAndLine) {
  const fs::path p =
      carmen_log("bad.log", kOdom1 +
                                "SONAR 0.261799 2 1.40 2.00 0.147 0.136 1.570796 0.193 0.119 "
                                "1100000000.050000 p2at 0.05\n");
  EXPECT_EQ(carmen_error_of(p),
            "bad.log:2: expected SONAR cone n range*n (x y theta)*n [robot_x robot_y robot_theta "
            "[tv rv]] timestamp host logger_ts at field 12, got 'p2at'");
  const fs::path q = carmen_log("bad2.log", kOdom1 + "SONAR 0.26 2 1.4\n");
  EXPECT_NE(carmen_error_of(q).find("bad2.log:2: expected SONAR cone n"), std::string::npos)
      << carmen_error_of(q);
  const fs::path r = carmen_log("bad3.log",
                                "ODOM 0 0 0 0 0 0 1100000000.0 p2at 0.0\n"
                                "ODOM 0 0 0 0 0 0 11000x0000.1 p2at 0.1\n");
  EXPECT_EQ(carmen_error_of(r), "bad3.log:2: expected timestamp at field 8, got '11000x0000.1'");
}

// What a hostile or broken file gets (was and is; checked when foreign_log_fuzz was added): a
// line of over 1 MiB is refused at that size (a 100 MB line is not buffered), a number that is
// not finite or a double (nan, inf, 1e400) or holds a NUL is refused naming its field, and a
// directory or a FIFO is refused before it is opened (a FIFO would wait for a writer).
TEST(CarmenImport, HostileFilesAreRefusedNamingFileAndLine) {
  const std::string overlong = kOdom1 + "SONAR 0.2 1 " + std::string((1u << 20) + 1, '1');
  EXPECT_EQ(carmen_error_of(carmen_log("long.log", overlong)),
            "long.log:2: line longer than 1048576 bytes: not a text log");
  const std::pair<std::string, std::string> numbers[] = {
      {"nan", "nan"}, {"-inf", "-inf"}, {"1e400", "1e400"}, {std::string("1\0.5", 4), "1\\x00.5"}};
  for (const auto& [v, quoted] : numbers) {
    EXPECT_EQ(carmen_error_of(
                  carmen_log("n.log", kOdom1 + "ODOM " + v + " 0 0 0 0 0 1100000000.1 h 0\n")),
              "n.log:2: expected x at field 2, got '" + quoted + "'");
    EXPECT_EQ(carmen_error_of(carmen_log("s.log", kOdom1 + "SONAR 0.2 1 " + v +
                                                      " 0.147 0.136 1.570796 1100000000.05 h 0\n")),
              "s.log:2: expected range at field 4, got '" + quoted + "'");
  }
  // A field too many was "at field 12, got 'end of line'".
  EXPECT_EQ(
      carmen_error_of(carmen_log("x.log", kOdom1 + "ODOM 1 0 0 0 0 0 1100000000.1 h 0 extra\n")),
      "x.log:2: ODOM has 10 fields where CARMEN writes 9 (x y theta tv rv accel timestamp "
      "host logger_ts): field 11 'extra' is one too many");
  EXPECT_EQ(carmen_error_of(carmen_log("c.log", kOdom1 + "SONAR 0.2 2147483648 1 1 1 1 h 0\n")),
            "c.log:2: expected num_sonars (0..255) at field 3, got '2147483648'");
  const fs::path dir = carmen_log("d.log", "").parent_path() / "a_directory.log";
  fs::create_directories(dir);
  const fs::path fifo = dir.parent_path() / "a_fifo.log";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const fs::path& p : {dir, fifo}) {
    const std::string want =
        p.filename().string() + ": not a regular file (a device, pipe or directory)";
    EXPECT_EQ(carmen_error_of(p), want);
    EXPECT_EQ(testing::import_error([](const fs::path& f) { return detect_log_format(f); }, p),
              want);
    EXPECT_EQ(testing::import_error([](const fs::path& f) { return import_player_log(f); }, p),
              want);
  }
}

}  // namespace
}  // namespace cogmap::hw
