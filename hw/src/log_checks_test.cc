// Every log reader refuses what would crash the mapper or fill the disk (issue 12): numbers that
// are not finite, time going back, odometry jumps, impossible header geometry, logs without
// frames and files that are not files, each with the file and line.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cogmap/hw/log_import.h"
#include "cogmap/hw/log_robot.h"
#include "cogmap/hw/robot_log.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;

const std::string kHeader =
    "cogmap-log 1 sonar_min_range_m=0.1 sonar_max_range_m=5 sonar_beam_width_rad=0.5236 "
    "length_m=0.626 width_m=0.505 max_speed_mps=0.75 max_turn_rate_radps=1.74 "
    "max_accel_mps2=0.3 max_decel_mps2=0.6 sonars=2 0.147,0.136,1.5708 0.193,0.119,0.8727";

fs::path write_log(const std::string& name, const std::string& text) {
  // One folder per test: ctest -j runs the tests of this file in parallel processes.
  const fs::path dir = fs::path(::testing::TempDir()) / "log_checks_test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

// A 5-frame log moving 1 cm per 100 ms, with `frame3` as its third frame line (line 4).
std::string log_with(const std::string& header, const std::string& frame3) {
  return header + "\nF 0.1 0.01 0 0 0 0 - 1 0,1.5,1,0.1\nF 0.2 0.02 0 0 0 0 - 0\n" + frame3 +
         "\nF 0.4 0.04 0 0 0 0 - 0\n";
}

std::string error_of(const std::string& text) {
  const fs::path p = write_log("l.log", text);
  try {
    LogRobot robot(p);
  } catch (const LogError& e) {
    const std::string what = e.what();
    return what.substr(what.find("l.log"));
  }
  return "";
}

TEST(LogChecks, ValidLogPasses) {
  EXPECT_EQ(error_of(log_with(kHeader, "F 0.3 0.03 0 0 0 0 - 0")), "");
}

TEST(LogChecks, NonFiniteNumbersNameTheLine) {
  EXPECT_EQ(error_of(log_with(kHeader, "F 0.3 nan 0 0 0 0 - 0")),
            "l.log:4: expected odometry x_m (a finite number), got 'nan'");
  EXPECT_EQ(error_of(log_with(kHeader, "F inf 0.03 0 0 0 0 - 0")),
            "l.log:4: expected time_s (a finite number), got 'inf'");
  EXPECT_EQ(error_of(log_with(kHeader, "F 0.3 0.03 0 0 0 0 -inf,0,0 0")),
            "l.log:4: expected true x_m (a finite number), got '-inf'");
  EXPECT_EQ(error_of(log_with(kHeader, "F 0.3 0.03 0 0 0 0 - 1 0,nan,1,0.3")),
            "l.log:4: expected range_m (a finite number), got 'nan'");
}

TEST(LogChecks, TimeBackwardsAndOdometryJumpsAreRefused) {
  EXPECT_EQ(error_of(log_with(kHeader, "F 0.15 0.03 0 0 0 0 - 0")),
            "l.log:4: time goes backwards (0.15 s after 0.2 s)");
  // 0.1 s at 0.75 m/s: at most 1 + 2 x 0.075 = 1.15 m.
  EXPECT_EQ(error_of(log_with(kHeader, "F 0.3 1.2 0 0 0 0 - 0")),
            "l.log:4: odometry jumps 1.18 m in 0.1 s (at most 1.15 m at max_speed_mps 0.75)");
  EXPECT_EQ(error_of(log_with(kHeader, "F 0.3 1.1 0 0 0 0 - 0")).find("l.log:4"),
            std::string::npos);  // 1.08 m passes frame 3 ...
  EXPECT_EQ(error_of(log_with(kHeader, "F 0.3 1e5 0 0 0 0 - 0")),
            "l.log:4: odometry x_m must be in [-1000, 1000], got 100000");
}

TEST(LogChecks, ImpossibleHeaderGeometryIsRefused) {
  auto with = [](const std::string& from, const std::string& to) {
    std::string h = kHeader;
    h.replace(h.find(from), from.size(), to);
    return log_with(h, "F 0.3 0.03 0 0 0 0 - 0");
  };
  EXPECT_EQ(error_of(with("sonar_max_range_m=5", "sonar_max_range_m=0")),
            "l.log:1: header: sonar_max_range_m must be in [0.05, 50], got 0");
  EXPECT_EQ(error_of(with("sonar_beam_width_rad=0.5236", "sonar_beam_width_rad=100")),
            "l.log:1: header: sonar_beam_width_rad must be in [0.001, 3.14159], got 100");
  EXPECT_EQ(error_of(with("sonar_min_range_m=0.1", "sonar_min_range_m=6")),
            "l.log:1: header: sonar_min_range_m must be in [0, 5], got 6");
  EXPECT_EQ(error_of(with("max_speed_mps=0.75", "max_speed_mps=0")),
            "l.log:1: header: max_speed_mps must be in [0.001, 10], got 0");
  EXPECT_EQ(error_of(with("0.147,0.136", "nan,0.136")),
            "l.log:1: expected sonar x_m (a finite number), got 'nan'");
}

TEST(LogChecks, HeaderOnlyAndForeignFilesAreRefused) {
  EXPECT_EQ(error_of(kHeader + "\n# nothing else\n"),
            "l.log:2: the log has a header but no frames (F lines): nothing to replay");
  try {
    LogRobot robot("/dev/zero");
    FAIL() << "read /dev/zero";
  } catch (const LogError& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/zero: not a regular file (a device, pipe or directory)");
  }
  // A cogmap log read as CARMEN has no CARMEN lines at all.
  const fs::path p = write_log("c.log", log_with(kHeader, "F 0.3 0.03 0 0 0 0 - 0"));
  try {
    (void)import_carmen_log(p);
    FAIL() << "imported a cogmap log as CARMEN";
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find("c.log: no ODOM or SONAR lines: not a CARMEN log"),
              std::string::npos)
        << e.what();
  }
}

TEST(LogChecks, OverlongLineIsRefusedNotBuffered) {
  LogLimits limits;
  limits.max_line_bytes = 64;
  const fs::path p = write_log("long.log", kHeader + "\n");
  try {
    LogReader reader(p, limits);  // the header alone is 248 bytes
    FAIL() << "read a line over the limit";
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find("long.log:1: line longer than 64 bytes"),
              std::string::npos)
        << e.what();
  }
}

TEST(LogChecks, ImportedFramesGetTheSameChecks) {
  const fs::path p = write_log(
      "jump.carmen.log",
      "ODOM 0 0 0 0 0 0 100.0 h 0\nODOM 0.05 0 0 0 0 0 100.1 h 0\nODOM 50 0 0 0 0 0 100.2 h 0\n");
  try {
    (void)import_carmen_log(p);
    FAIL() << "imported a 50 m jump";
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find("jump.carmen.log:3: odometry jumps 49.95 m in 0.1"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace cogmap::hw
