// The cogmap log: exact round trip through RecordingRobot and LogRobot, strict errors with
// file:line, and the CARMEN and Player importers on the sample files in hw/testdata.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "cogmap/hw/log_import.h"
#include "cogmap/hw/log_robot.h"
#include "cogmap/mapper/seam/fake_robot.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;

fs::path testdata(const std::string& name) { return fs::path(COGMAP_HW_TESTDATA) / name; }

fs::path temp_file(const std::string& name) { return test_support::process_scratch() / name; }

void write_file(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::vector<mapper::SensorFrame> sample_frames() {
  std::vector<mapper::SensorFrame> frames;
  for (int i = 0; i < 5; ++i) {
    mapper::SensorFrame f;
    f.time_s = 0.1 * (i + 1);
    f.odometry = {0.1 / 3.0 * i, -1e-17 * i, 3.141592653589793 - 0.3 * i};
    f.stall_left = i == 2;
    f.stall_right = i == 3;
    if (i % 2 == 0) f.true_pose = mapper::Pose2{1.0 + i, 2.0 / 7.0, -0.5};
    for (int k = 0; k < i; ++k) {
      f.sonar.push_back({k * 3, 0.1 + 1.0 / (k + 3), k != 1, f.time_s - 0.01 * k});
    }
    frames.push_back(f);
  }
  return frames;
}

void expect_same(const mapper::SensorFrame& a, const mapper::SensorFrame& b) {
  EXPECT_EQ(a.time_s, b.time_s);  // bit-identical: shortest round-trip formatting
  EXPECT_EQ(a.odometry.x_m, b.odometry.x_m);
  EXPECT_EQ(a.odometry.y_m, b.odometry.y_m);
  EXPECT_EQ(a.odometry.theta_rad, b.odometry.theta_rad);
  EXPECT_EQ(a.stall_left, b.stall_left);
  EXPECT_EQ(a.stall_right, b.stall_right);
  ASSERT_EQ(a.true_pose.has_value(), b.true_pose.has_value());
  if (a.true_pose) {
    EXPECT_EQ(a.true_pose->x_m, b.true_pose->x_m);
    EXPECT_EQ(a.true_pose->y_m, b.true_pose->y_m);
    EXPECT_EQ(a.true_pose->theta_rad, b.true_pose->theta_rad);
  }
  ASSERT_EQ(a.sonar.size(), b.sonar.size());
  for (std::size_t i = 0; i < a.sonar.size(); ++i) {
    EXPECT_EQ(a.sonar[i].index, b.sonar[i].index);
    EXPECT_EQ(a.sonar[i].range_m, b.sonar[i].range_m);
    EXPECT_EQ(a.sonar[i].echo, b.sonar[i].echo);
    EXPECT_EQ(a.sonar[i].time_s, b.sonar[i].time_s);
  }
}

TEST(RobotLog, RecordThenReplayIsBitIdentical) {
  const auto frames = sample_frames();
  mapper::FakeRobot inner(mapper::p2at_geometry(), frames);
  const fs::path path = temp_file("roundtrip.log");
  {
    RecordingRobot rec(inner, path);
    while (auto f = rec.next_frame()) rec.command({0.25, -0.125});
    rec.stop();
  }
  ASSERT_EQ(inner.commands().size(), 6u);  // passed through
  LogRobot replay(path);
  EXPECT_EQ(replay.frame_count(), 5u);
  EXPECT_FALSE(replay.has_true_poses());  // only some frames carry one
  EXPECT_EQ(replay.geometry().sonars.size(), 16u);
  EXPECT_EQ(replay.geometry().sonars[9].heading_rad, mapper::p2at_geometry().sonars[9].heading_rad);
  for (const auto& expected : frames) {
    auto got = replay.next_frame();
    ASSERT_TRUE(got);
    expect_same(expected, *got);
  }
  EXPECT_FALSE(replay.next_frame());
  // The commands are in the log, after the frame they followed.
  LogReader reader(path);
  int commands = 0, stops = 0;
  while (auto item = reader.next()) {
    if (auto* c = std::get_if<LoggedCommand>(&*item)) {
      (c->stop ? stops : commands) += 1;
      if (!c->stop) {
        EXPECT_EQ(c->cmd.w_radps, -0.125);
      }
    }
  }
  EXPECT_EQ(commands, 5);
  EXPECT_EQ(stops, 1);
}

TEST(RobotLog, EveryLineIsFlushedAsWritten) {
  mapper::FakeRobot inner(mapper::p2at_geometry(), sample_frames());
  const fs::path path = temp_file("flush.log");
  RecordingRobot rec(inner, path);
  rec.next_frame();
  rec.next_frame();
  // Still open: a crash now would keep both frames.
  LogRobot partial(path);
  EXPECT_EQ(partial.frame_count(), 2u);
}

void expect_error(const fs::path& path, const std::string& where, const std::string& what) {
  try {
    LogRobot robot(path);
    FAIL() << "expected LogError for " << path;
  } catch (const LogError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(where), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

TEST(RobotLog, MalformedLinesNameFileLineAndExpectation) {
  expect_error(testdata("bad_reading.cogmap.log"), "bad_reading.cogmap.log:4:", "range_m");
  const std::string header = format_log_header(mapper::p2at_geometry()) + "\n";
  const fs::path p = temp_file("bad.log");
  write_file(p, header + "F 0.1 0 0 0 0 0 - 0\nX 1 2\n");
  expect_error(p, "bad.log:3:", "a line type F, C or S");
  write_file(p, header + "F 0.1 0 0 0 2 0 - 0\n");
  expect_error(p, "bad.log:2:", "stall_left");
  write_file(p, header + "F 0.1 0 0 0 0 0 - 2 1,2,1,0.1\n");
  expect_error(p, "bad.log:2:", "reading index,range_m,echo,time_s (2 of 2)");
  write_file(p, header + "F 0.1 0 0 0 0 0 - 1 16,2,1,0.1\n");
  expect_error(p, "bad.log:2:", "sonar index");
  write_file(p, header + "F 0.1 0 0 0 0 0 1,2 0\n");
  expect_error(p, "bad.log:2:", "true pose");
  write_file(p, header + "C 0.1 0.5\n");
  expect_error(p, "bad.log:2:", "w_radps");
  write_file(p, header + "F 0.1 0 0 0 0 0 - 0 extra\n");
  expect_error(p, "bad.log:2:", "end of line");
  write_file(p, "cogmap-log 2 whatever\n");
  expect_error(p, "bad.log:1:", "format version 1");
  write_file(p, "# only a comment\n");
  expect_error(p, "bad.log:2:", "header");
  write_file(p, "cogmap-log 1 sonar_min_range_m=0.1\n");
  expect_error(p, "bad.log:1:", "sonar_max_range_m=VALUE");
  expect_error(temp_file("does_not_exist.log"), "does_not_exist.log", "cannot open");
}

TEST(LogImport, CarmenOdomAndSonar) {
  EXPECT_EQ(detect_log_format(testdata("sample.carmen.log")), LogFormat::kCarmen);
  const ImportedLog log = import_carmen_log(testdata("sample.carmen.log"));
  EXPECT_EQ(log.ignored_lines, 2u);  // PARAM, FLASER
  ASSERT_EQ(log.frames.size(), 4u);
  ASSERT_EQ(log.geometry.sonars.size(), 4u);
  EXPECT_DOUBLE_EQ(log.geometry.sonars[1].x_m, 0.193);
  EXPECT_DOUBLE_EQ(log.geometry.sonar_beam_width_rad, 0.523599);
  const auto& s = log.frames[1];
  EXPECT_NEAR(s.time_s, 0.05, 1e-6);
  ASSERT_EQ(s.sonar.size(), 4u);
  EXPECT_TRUE(s.sonar[0].echo);
  EXPECT_DOUBLE_EQ(s.sonar[1].range_m, 2.25);
  EXPECT_FALSE(s.sonar[2].echo);  // 5.00 = max range
  EXPECT_FALSE(s.sonar[3].echo);  // 0 = no echo
  EXPECT_NEAR(log.frames[2].odometry.x_m, 0.05, 1e-12);
  EXPECT_NEAR(log.frames[2].odometry.theta_rad, 0.01, 1e-12);
  // The last SONAR line has no tv rv fields: still read.
  EXPECT_NEAR(log.frames[3].odometry.theta_rad, 0.02, 1e-12);
  EXPECT_EQ(log.frames[3].sonar.size(), 2u);

  const fs::path p = temp_file("bad.carmen.log");
  write_file(p, "ODOM 0 0 0 0 0 0 1.0 host\n");
  try {
    import_carmen_log(p);
    FAIL();
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.carmen.log:1:"), std::string::npos) << e.what();
  }
  write_file(p, "ODOM 0 0 0 0 0 0 1.0 host 0\nSONAR 0.5 2 1.0 x 0 0 0 0 0 0 0 0 0 1.1 h 0.1\n");
  try {
    import_carmen_log(p);
    FAIL();
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.carmen.log:2: expected range at field 5"),
              std::string::npos)
        << e.what();
  }
}

TEST(LogImport, PlayerPositionAndSonar) {
  EXPECT_EQ(detect_log_format(testdata("sample.player.log")), LogFormat::kPlayer);
  const ImportedLog log = import_player_log(testdata("sample.player.log"));
  EXPECT_EQ(log.ignored_lines, 1u);  // laser
  ASSERT_EQ(log.geometry.sonars.size(), 4u);
  EXPECT_DOUBLE_EQ(log.geometry.sonars[3].heading_rad, 0.175);
  ASSERT_EQ(log.frames.size(), 3u);
  EXPECT_EQ(log.frames[0].sonar.size(), 4u);
  EXPECT_NEAR(log.frames[0].time_s, 0.1, 1e-6);
  EXPECT_TRUE(log.frames[1].sonar.empty());  // a position line with no sonar after it
  EXPECT_NEAR(log.frames[1].odometry.x_m, 0.05, 1e-12);
  EXPECT_NEAR(log.frames[2].odometry.x_m, 0.1, 1e-12);
  EXPECT_TRUE(log.frames[2].stall_left);
  EXPECT_NEAR(log.frames[2].sonar[1].range_m, 4.2, 1e-12);

  // An import written as a cogmap log replays the same frames.
  const fs::path out = temp_file("player.cogmap.log");
  write_cogmap_log(out, log);
  EXPECT_EQ(detect_log_format(out), LogFormat::kCogmap);
  LogRobot replay(out);
  EXPECT_EQ(replay.geometry().sonars.size(), 4u);
  for (const auto& f : log.frames) expect_same(f, *replay.next_frame());

  const fs::path p = temp_file("bad.player.log");
  write_file(p, "1.0 1 6665 sonar 00 001 001 0003 +1.0 +2.0\n");
  try {
    import_player_log(p);
    FAIL();
  } catch (const LogError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.player.log:1:"), std::string::npos) << e.what();
  }
  write_file(p, "garbage line\n");
  EXPECT_THROW(detect_log_format(p), LogError);
}

}  // namespace
}  // namespace cogmap::hw
