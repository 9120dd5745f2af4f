// Every log reader refuses what would crash the mapper or fill the disk (issue 12): numbers that
// are not finite, time going back, odometry jumps, impossible header geometry, logs without
// frames and files that are not files, each with the file and line.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "cogmap/hw/log_import.h"
#include "cogmap/hw/log_robot.h"
#include "cogmap/hw/robot_log.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;

const std::string kChecksHeader =
    "cogmap-log 1 sonar_min_range_m=0.1 sonar_max_range_m=5 sonar_beam_width_rad=0.5236 "
    "length_m=0.626 width_m=0.505 max_speed_mps=0.75 max_turn_rate_radps=1.74 "
    "max_accel_mps2=0.3 max_decel_mps2=0.6 sonars=2 0.147,0.136,1.5708 0.193,0.119,0.8727";

fs::path checks_log(const std::string& name, const std::string& text) {
  // One folder per test: ctest -j runs the tests of this file in parallel processes.
  const fs::path dir = test_support::process_scratch() / "log_checks_test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

// A 4-frame log moving 1 cm per 100 ms, with `frame3` as its third frame line (line 4).
std::string log_with(const std::string& header, const std::string& frame3) {
  return header + "\nF 0.1 0.01 0 0 0 0 - 1 0,1.5,1,0.1\nF 0.2 0.02 0 0 0 0 - 0\n" + frame3 +
         "\nF 0.4 0.04 0 0 0 0 - 0\n";
}

std::string checks_error_of(const std::string& text) {
  const fs::path p = checks_log("l.log", text);
  try {
    LogRobot robot(p);
  } catch (const LogError& e) {
    const std::string what = e.what();
    return what.substr(what.find("l.log"));
  }
  return "";
}

TEST(LogChecks, ValidLogPasses) {
  EXPECT_EQ(checks_error_of(log_with(kChecksHeader, "F 0.3 0.03 0 0 0 0 - 0")), "");
}

TEST(LogChecks, NonFiniteNumbersNameTheLine) {
  EXPECT_EQ(checks_error_of(log_with(kChecksHeader, "F 0.3 nan 0 0 0 0 - 0")),
            "l.log:4: expected odometry x_m (a finite number), got 'nan'");
  EXPECT_EQ(checks_error_of(log_with(kChecksHeader, "F inf 0.03 0 0 0 0 - 0")),
            "l.log:4: expected time_s (a finite number), got 'inf'");
  EXPECT_EQ(checks_error_of(log_with(kChecksHeader, "F 0.3 0.03 0 0 0 0 -inf,0,0 0")),
            "l.log:4: expected true x_m (a finite number), got '-inf'");
  EXPECT_EQ(checks_error_of(log_with(kChecksHeader, "F 0.3 0.03 0 0 0 0 - 1 0,nan,1,0.3")),
            "l.log:4: expected range_m (a finite number), got 'nan'");
}

TEST(LogChecks, TimeBackwardsAndOdometryJumpsAreRefused) {
  EXPECT_EQ(checks_error_of(log_with(kChecksHeader, "F 0.15 0.03 0 0 0 0 - 0")),
            "l.log:4: time goes backwards (0.15 s after 0.2 s)");
  // 0.1 s at 0.75 m/s: at most 1 + 2 x 0.075 = 1.15 m.
  EXPECT_EQ(checks_error_of(log_with(kChecksHeader, "F 0.3 1.2 0 0 0 0 - 0")),
            "l.log:4: odometry jumps 1.18 m in 0.1 s (at most 1.15 m at max_speed_mps 0.75)");
  EXPECT_EQ(checks_error_of(log_with(kChecksHeader, "F 0.3 1.1 0 0 0 0 - 0")).find("l.log:4"),
            std::string::npos);  // 1.08 m passes frame 3 ...
  EXPECT_EQ(checks_error_of(log_with(kChecksHeader, "F 0.3 1e5 0 0 0 0 - 0")),
            "l.log:4: odometry x_m must be in [-1000, 1000], got 100000");
}

TEST(LogChecks, ImpossibleHeaderGeometryIsRefused) {
  auto with = [](const std::string& from, const std::string& to) {
    std::string h = kChecksHeader;
    h.replace(h.find(from), from.size(), to);
    return log_with(h, "F 0.3 0.03 0 0 0 0 - 0");
  };
  EXPECT_EQ(checks_error_of(with("sonar_max_range_m=5", "sonar_max_range_m=0")),
            "l.log:1: header: sonar_max_range_m must be in [0.05, 50], got 0");
  EXPECT_EQ(checks_error_of(with("sonar_beam_width_rad=0.5236", "sonar_beam_width_rad=100")),
            "l.log:1: header: sonar_beam_width_rad must be in [0.001, 3.14159], got 100");
  EXPECT_EQ(checks_error_of(with("sonar_min_range_m=0.1", "sonar_min_range_m=6")),
            "l.log:1: header: sonar_min_range_m must be in [0, 5], got 6");
  EXPECT_EQ(checks_error_of(with("max_speed_mps=0.75", "max_speed_mps=0")),
            "l.log:1: header: max_speed_mps must be in [0.001, 10], got 0");
  EXPECT_EQ(checks_error_of(with("0.147,0.136", "nan,0.136")),
            "l.log:1: expected sonar x_m (a finite number), got 'nan'");
}

TEST(LogChecks, HeaderOnlyAndForeignFilesAreRefused) {
  EXPECT_EQ(checks_error_of(kChecksHeader + "\n# nothing else\n"),
            "l.log:2: the log has a header but no frames (F lines): nothing to replay");
  try {
    LogRobot robot("/dev/zero");
    FAIL() << "read /dev/zero";
  } catch (const LogError& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/zero: not a regular file (a device, pipe or directory)");
  }
  // A cogmap log read as CARMEN has no CARMEN lines at all.
  const fs::path p = checks_log("c.log", log_with(kChecksHeader, "F 0.3 0.03 0 0 0 0 - 0"));
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
  const fs::path p = checks_log("long.log", kChecksHeader + "\n");
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
  const fs::path p = checks_log(
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

// Logs as they come from elsewhere (the 2026-12-07 audit). A UTF-8 byte order mark, which
// Windows editors put before the first line, made the first word "\xef\xbb\xbfcogmap-log": the
// log was refused as "expected a cogmap, CARMEN or Player log line, got 'cogmap-log 1 ...'",
// and the mark itself was invisible in the message. CRLF line ends were already read.
TEST(LogChecks, ByteOrderMarkAndCrlfAreRead) {
  const std::string bom = "\xef\xbb\xbf";
  std::string crlf = bom + log_with(kChecksHeader, "F 0.3 0.03 0 0 0 0 - 0");
  for (std::size_t at = crlf.find('\n'); at != std::string::npos; at = crlf.find('\n', at + 2)) {
    crlf.insert(at, "\r");
  }
  for (const std::string& text : {bom + log_with(kChecksHeader, "F 0.3 0.03 0 0 0 0 - 0"), crlf}) {
    const fs::path p = checks_log("bom.log", text);
    EXPECT_EQ(detect_log_format(p), LogFormat::kCogmap);
    LogRobot robot(p);
    EXPECT_EQ(robot.frame_count(), 4u);
    EXPECT_EQ(robot.geometry().sonars.size(), 2u);
  }
  const fs::path carmen =
      checks_log("bom.carmen.log",
                 bom +
                     "# CARMEN log\nODOM 0 0 0 0 0 0 100.0 h 0\nODOM 0.05 0 0 0 0 0 100.1 h 0\n"
                     "SONAR 0.5 1 1.5 0.1 0 0 100.1 h 0\n");
  EXPECT_EQ(detect_log_format(carmen), LogFormat::kCarmen);
  EXPECT_EQ(import_carmen_log(carmen).frames.size(), 3u);
  const fs::path player =
      checks_log("bom.player.log", bom +
                                       "## Player version 2.0.5\n"
                                       "1.0 h 6665 position2d 00 001 001 0 0 0 0 0 0 0\n"
                                       "1.1 h 6665 position2d 00 001 001 0.05 0 0 0 0 0 0\n"
                                       "1.1 h 6665 sonar 00 001 001 1 1.5\n");
  EXPECT_EQ(detect_log_format(player), LogFormat::kPlayer);
  EXPECT_EQ(import_player_log(player).frames.size(), 2u);
}

std::string any_error(const std::function<void()>& read) {
  try {
    read();
  } catch (const LogError& e) {
    return e.what();
  }
  return "accepted";
}

// Logs are shipped compressed (CARMEN logs as .log.gz): each reader said "expected a cogmap,
// CARMEN or Player log line, got '" and the compressed bytes, raw, up to a NUL that ended the
// message. Now the file is named for what it is.
TEST(LogChecks, CompressedOrUtf16LogsSayWhatTheyAre) {
  const std::pair<std::string, std::string> cases[] = {
      {std::string("\x1f\x8b\x08\x08\x00\x00\x00\x00", 8), "gzip-compressed: decompress it first"},
      {"BZh91AY&SY", "bzip2-compressed"},
      {std::string("\xfd"
                   "7zXZ\0\0\x04",
                   8),
       "xz-compressed"},
      {std::string("\xff\xfe"
                   "c\0o\0g\0",
                   8),
       "UTF-16 text"},
  };
  for (const auto& [bytes, what] : cases) {
    const fs::path p = checks_log("packed.log", bytes + std::string(100, '\x01'));
    for (const auto& read : std::vector<std::function<void()>>{
             [&] { (void)detect_log_format(p); }, [&] { LogRobot robot(p); },
             [&] { (void)import_carmen_log(p); }, [&] { (void)import_player_log(p); }}) {
      const std::string e = any_error(read);
      EXPECT_NE(e.find("packed.log: not a text log: " + what), std::string::npos) << e;
    }
  }
}

// Whatever a line holds, the message quoting it is printable and short: bytes outside printable
// ASCII as \xNN (a NUL ended the message, binary reached the terminal), at most 80 of them.
TEST(LogChecks, MessagesQuoteBinaryEscapedAndShort) {
  const std::string binary =
      std::string("F\x01\x1b[2J", 6) + std::string(1, '\0') + "\xc3" + std::string(5000, 'z');
  std::string e =
      checks_error_of(log_with(kChecksHeader, "F 0.3 0.03 0 0 0 0 - 0") + binary + "\n");
  EXPECT_EQ(e, "l.log:6: expected a line type F, C or S, got 'F\\x01\\x1b[2J\\x00\\xc3" +
                   std::string(72, 'z') + "... (5008 bytes)'");
  const fs::path p = checks_log("binary.carmen.log",
                                "ODOM 0 0 0 0 0 0 100.0 h 0\nODOM \x01\x02 0 0 0 0 0 100.1 h 0\n");
  EXPECT_NE(any_error([&] {
              (void)import_carmen_log(p);
            }).find("binary.carmen.log:2: expected x at field 2, got '\\x01\\x02'"),
            std::string::npos);
}

// A file whose last blocks were allocated but never written ends in NUL bytes (power lost while
// recording): said as such, not quoted as a line type.
TEST(LogChecks, NulTailSaysTheEndWasNeverWritten) {
  EXPECT_EQ(
      checks_error_of(log_with(kChecksHeader, "F 0.3 0.03 0 0 0 0 - 0") + std::string(4096, '\0')),
      "l.log:6: 4096 NUL bytes instead of a line: the end of the file was never written "
      "(power lost or disk full while recording?); the lines before it are whole, cut the "
      "file there to use them");
}

// The writer flushes whole lines, so a last line without its newline was cut while being
// written: the message says so.
TEST(LogChecks, LastLineCutShortSaysSo) {
  const std::string whole = log_with(kChecksHeader, "F 0.3 0.03 0 0 0 0 - 0");
  const std::string note =
      " (the last line, cut short: no newline ends it, so the recording stopped while writing "
      "it; the lines before it are whole: delete this one to replay them)";
  EXPECT_EQ(checks_error_of(whole + "F 0.5 0.05 0 0 0 0 - 2 0,1.5,1,0.5 1,2.2"),
            "l.log:6: expected reading index,range_m,echo,time_s (2 of 2), got '1,2.2'" + note);
  EXPECT_EQ(checks_error_of(whole + "F 0.5 0.0"),
            "l.log:6: expected odometry y_m, got 'end of line'" + note);
  // A malformed line that is not the last, or a last line that parses, is as before.
  EXPECT_EQ(checks_error_of(whole + "F 0.5 0.05 0 0 0 0 - 2\nF 0.6 0.06 0 0 0 0 - 0\n"),
            "l.log:6: expected reading index,range_m,echo,time_s (1 of 2), got 'end of line'");
  EXPECT_EQ(checks_error_of(whole + "F 0.5 0.05 0 0 0 0 - 0"), "");
}

}  // namespace
}  // namespace cogmap::hw
