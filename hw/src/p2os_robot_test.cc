// P2osRobot against the robot-side server on a pseudo-terminal, with faults injected on the
// server's side of the link: left open, corruption, silence, controller reset, counter wrap.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

#include <poll.h>
#include <unistd.h>

#include "cogmap/hw/fd_stream.h"
#include "cogmap/hw/p2os_robot.h"
#include "cogmap/hw/p2os_server.h"
#include "test_streams.h"

namespace cogmap::hw {
namespace {

using namespace std::chrono_literals;
using testing::frames_for;
using testing::KinematicBody;

// A served robot on a pty: the server runs in a thread on the master end (through `link`,
// which tests may decorate); clients open the slave like a serial port.
class PtyRobot {
 public:
  explicit PtyRobot(P2osServerOptions options = {}, ByteStream* link = nullptr)
      : pty_(open_pty()),
        link_(link ? link : pty_->master.get()),
        server_(*link_, body_, std::move(options)) {}
  void start() {
    thread_ = std::thread([this] { server_.run(stop_); });
  }
  ~PtyRobot() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  std::unique_ptr<ByteStream> client() { return open_serial_port(pty_->slave_path, 9600); }
  ByteStream& master() { return *pty_->master; }
  KinematicBody& body() { return body_; }
  P2osServer& server() { return server_; }

 private:
  std::unique_ptr<Pty> pty_;
  KinematicBody body_;
  ByteStream* link_;
  P2osServer server_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Consecutive frames' odometry never more than 0.1 m apart (a SIP is 0.1 s; the body drives at
// most 0.75 m/s).
void expect_no_odometry_jump(const std::vector<mapper::SensorFrame>& frames) {
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const auto& a = frames[i - 1].odometry;
    const auto& b = frames[i].odometry;
    EXPECT_LT(std::hypot(b.x_m - a.x_m, b.y_m - a.y_m), 0.1) << "frame " << i;
  }
}

P2osRobotOptions fast_options() {
  P2osRobotOptions o;
  o.silence_timeout = 2000ms;
  o.reconnect_give_up = 15000ms;
  o.frame_wait = 5000ms;
  return o;
}

TEST(P2osRobotPty, HandshakeFramesSonarAndCommands) {
  PtyRobot served;
  served.start();
  P2osRobot robot(served.client(), fast_options());
  EXPECT_EQ(robot.identity().subclass, "p2at");
  EXPECT_EQ(robot.identity().klass, "Pioneer");
  robot.command({0.3, 0.0});
  const auto frames = frames_for(robot, 1500ms);
  ASSERT_GE(frames.size(), 10u);
  // Sonar: index and range survive the 0.268 mm unit; transducer 15 reports no echo.
  bool saw_echo = false, saw_no_echo = false;
  for (const auto& f : frames) {
    for (const auto& r : f.sonar) {
      if (r.index == 15) {
        EXPECT_FALSE(r.echo);
        EXPECT_DOUBLE_EQ(r.range_m, robot.geometry().sonar_max_range_m);
        saw_no_echo = true;
      } else {
        EXPECT_TRUE(r.echo);
        EXPECT_NEAR(r.range_m, 1.0 + 0.1 * r.index, 0.0003);
        saw_echo = true;
      }
    }
  }
  EXPECT_TRUE(saw_echo);
  EXPECT_TRUE(saw_no_echo);
  EXPECT_NEAR(served.body().current().v_mps, 0.3, 1e-9);  // VEL 300 mm/s arrived
  // Odometry follows the body: 1.32 mm units.
  EXPECT_GT(frames.back().odometry.x_m, 0.2);
  EXPECT_NEAR(frames.back().odometry.y_m, 0.0, 0.002);
  // Clamping: far above the P2-AT limits.
  robot.command({5.0, -9.0});
  frames_for(robot, 400ms);
  EXPECT_NEAR(served.body().current().v_mps, 0.75, 1e-9);
  EXPECT_NEAR(served.body().current().w_radps, -100.0 * M_PI / 180.0, 1e-9);  // 99.7 -> 100 deg/s
  robot.shutdown();
  // After shutdown there are no frames, queued or new, and next_frame() does not wait.
  const auto asked = std::chrono::steady_clock::now();
  EXPECT_FALSE(robot.next_frame().has_value());
  EXPECT_LT(std::chrono::steady_clock::now() - asked, 100ms);
  std::this_thread::sleep_for(300ms);
  EXPECT_NEAR(served.body().current().v_mps, 0.0, 1e-9);  // STOP, CLOSE at shutdown
  EXPECT_EQ(served.server().stats().syncs, 1u);
}

TEST(P2osRobotPty, LeftOpenRobotIsClosedAndResynced) {
  PtyRobot served;
  served.start();
  {
    // A previous client syncs and opens, then vanishes without CLOSE.
    auto raw = served.client();
    using p2os::Command;
    for (Command c : {Command::kSync0, Command::kSync1, Command::kSync2}) {
      raw->write(p2os::encode_command(c));
      std::this_thread::sleep_for(50ms);
    }
    raw->write(p2os::encode_command(Command::kOpen));
    std::this_thread::sleep_for(400ms);  // SIPs now queue up in the pty
  }
  P2osRobot robot(served.client(), fast_options());
  EXPECT_GE(robot.stats().left_open_recoveries, 1);
  EXPECT_EQ(robot.identity().subclass, "p2at");
  EXPECT_GE(frames_for(robot, 600ms).size(), 3u);
}

TEST(P2osRobotPty, KeepAliveNeverLeavesHalfSecondGap) {
  auto pty = open_pty();
  testing::TappingStream tap(*pty->master);
  KinematicBody body;
  P2osServer server(tap, body);
  std::atomic<bool> stop{false};
  std::thread t([&] { server.run(stop); });
  {
    P2osRobot robot(open_serial_port(pty->slave_path, 9600), fast_options());
    robot.command({0.2, 0.1});  // one command, then only the keep-alive
    frames_for(robot, 3000ms);
    robot.shutdown();
  }
  stop = true;
  t.join();
  const auto arrivals = tap.arrivals();
  ASSERT_GE(arrivals.size(), 10u);
  // From OPEN (after sync) to CLOSE, no gap above the 0.5 s bound.
  std::size_t open_at = 0;
  while (open_at < arrivals.size() && arrivals[open_at].type != 4) ++open_at;  // ENABLE
  ASSERT_LT(open_at, arrivals.size());
  double max_gap_s = 0.0;
  for (std::size_t i = open_at + 1; i < arrivals.size(); ++i) {
    max_gap_s = std::max(
        max_gap_s, std::chrono::duration<double>(arrivals[i].time - arrivals[i - 1].time).count());
  }
  EXPECT_LT(max_gap_s, 0.5);
  EXPECT_EQ(server.stats().watchdog_stops, 0u);
  EXPECT_GT(body.distance_m(), 0.4);  // kept moving for the whole 3 s
}

TEST(P2osRobotPty, PositionWrapAcross7FFFKeepsMotion) {
  P2osServerOptions so;
  so.initial_x_count = 0x7F80;  // 128 units (17 cm) below the wrap
  so.initial_y_count = 0x7FF0;
  PtyRobot served(so);
  served.start();
  P2osRobot robot(served.client(), fast_options());
  robot.command({0.75, 0.0});
  const auto frames = frames_for(robot, 1500ms);
  robot.shutdown();
  ASSERT_GE(frames.size(), 10u);
  double prev = frames.front().odometry.x_m;
  for (const auto& f : frames) {
    EXPECT_GE(f.odometry.x_m, prev - 1e-9);  // monotonic through the wrap
    EXPECT_LT(f.odometry.x_m - prev, 0.2);   // no jump of 43 m
    EXPECT_NEAR(f.odometry.y_m, frames.front().odometry.y_m, 1e-9);
    prev = f.odometry.x_m;
  }
  const double travelled = frames.back().odometry.x_m - frames.front().odometry.x_m;
  EXPECT_GT(travelled, 0.17 * 2);  // crossed 0x7FFF (the start was 0.17 m below it)
}

TEST(P2osRobotPty, SurvivesOneCorruptedByteInFiveHundred) {
  auto pty = open_pty();
  testing::CorruptingStream corrupt(*pty->master, 500, 1234);
  KinematicBody body;
  P2osServer server(corrupt, body);
  std::atomic<bool> stop{false};
  std::thread t([&] { server.run(stop); });
  std::vector<mapper::SensorFrame> frames;
  P2osStats stats;
  {
    P2osRobot robot(open_serial_port(pty->slave_path, 9600), fast_options());
    robot.command({0.4, 0.0});
    frames = frames_for(robot, 6000ms);
    stats = robot.stats();
    robot.shutdown();
  }
  stop = true;
  t.join();
  EXPECT_GE(corrupt.flipped(), 4u);  // ~3000 bytes of SIPs at one flip per 500
  EXPECT_GT(stats.dropped_bytes, 0u);
  EXPECT_GE(frames.size(), 45u);  // at most one SIP lost per flip
  for (std::size_t i = 1; i < frames.size(); ++i) {
    EXPECT_LT(std::abs(frames[i].odometry.x_m - frames[i - 1].odometry.x_m), 0.2) << i;
  }
  EXPECT_NEAR(frames.back().odometry.x_m, 0.4 * (frames.size()) * 0.1, 0.6);
}

TEST(P2osRobotPty, SilentRobotComesBackWithoutLosingMotion) {
  auto pty = open_pty();
  testing::SilenceableStream link(*pty->master);
  KinematicBody body;
  P2osServer server(link, body);
  std::atomic<bool> stop{false};
  std::thread t([&] { server.run(stop); });
  std::vector<mapper::SensorFrame> frames;
  P2osStats stats;
  {
    P2osRobot robot(open_serial_port(pty->slave_path, 9600), fast_options());
    robot.command({0.3, 0.0});
    frames = frames_for(robot, 1000ms);
    link.silent = true;
    std::this_thread::sleep_for(3000ms);
    link.silent = false;
    auto more = frames_for(robot, 2500ms);
    frames.insert(frames.end(), more.begin(), more.end());
    stats = robot.stats();
    robot.shutdown();
  }
  stop = true;
  t.join();
  EXPECT_EQ(stats.connections, 2);
  EXPECT_GE(stats.left_open_recoveries, 1);  // it was still open when it came back
  ASSERT_GE(frames.size(), 20u);
  // The body never stopped (SYNC0 doubles as PULSE), and no motion was thrown away.
  EXPECT_NEAR(frames.back().odometry.x_m, body.distance_m(), 0.15);  // the gap alone is 0.9 m
}

TEST(P2osRobotPty, ControllerResetRebasesOdometryWithoutJump) {
  PtyRobot served;
  served.start();
  P2osRobot robot(served.client(), fast_options());
  robot.command({0.3, 0.2});
  auto frames = frames_for(robot, 1200ms);
  served.server().request_reset();
  auto more = frames_for(robot, 2500ms);
  frames.insert(frames.end(), more.begin(), more.end());
  const P2osStats stats = robot.stats();
  robot.shutdown();
  EXPECT_EQ(stats.resets, 1);
  EXPECT_EQ(stats.connections, 2);
  expect_no_odometry_jump(frames);
  EXPECT_GT(frames.back().odometry.x_m, frames[10].odometry.x_m);  // kept going after reset
}

// SIPs whose odometry moves further than the robot can drive (found by fuzzing: a peer's SIPs
// with valid checksums 48 m apart were mapped, `drive` exited 0) are undecodable, not frames:
// counted, named by stream offset, and a peer that sends nothing else is bad input.
TEST(P2osRobotPty, OdometryJumpingFurtherThanTheRobotDrivesIsNoFrame) {
  PtyRobot served;
  served.start();
  P2osRobot robot(served.client(), fast_options());
  robot.command({0.3, 0.0});
  auto frames = frames_for(robot, 800ms);
  ASSERT_GE(frames.size(), 4u);
  // 20 m within one 0.1 s SIP. 1 m + 2 x 0.75 m/s x dt is allowed since the last frame, so the
  // new place would be admitted after 12.7 s; the session ends first (2 s without a frame).
  served.body().teleport(20.0);
  const auto more = frames_for(robot, 8000ms);  // ends with the session
  frames.insert(frames.end(), more.begin(), more.end());
  const P2osStats stats = robot.stats();
  const std::string failure = robot.failure();
  const P2osFailureKind kind = robot.failure_kind();
  robot.shutdown();
  expect_no_odometry_jump(frames);
  EXPECT_GE(stats.bad_sips, 5u);
  EXPECT_EQ(kind, P2osFailureKind::kBadBytes);
  EXPECT_NE(failure.find("SIP at stream offset"), std::string::npos) << failure;
  EXPECT_NE(failure.find("odometry jumps"), std::string::npos) << failure;
}

TEST(P2osRobotPty, SubclassP2at8PlusSelectsItsConversionFactors) {
  P2osServerOptions so;
  so.identity = {"plus", "Pioneer", "p2at8+"};  // 0.465 mm per position unit, 1 mm sonar unit
  PtyRobot served(so);
  served.start();
  P2osRobot robot(served.client(), fast_options());
  EXPECT_EQ(robot.identity().subclass, "p2at8+");
  robot.command({0.5, 0.0});
  const auto frames = frames_for(robot, 1200ms);
  robot.shutdown();
  ASSERT_GE(frames.size(), 8u);
  for (const auto& f : frames) {
    for (const auto& r : f.sonar) {
      if (r.echo) {
        EXPECT_NEAR(r.range_m, 1.0 + 0.1 * r.index, 0.0005);  // 1 mm units
      }
    }
  }
  // Body and client agree on distance only if both used 0.465 mm per unit.
  const double per_frame_m = (frames.back().odometry.x_m - frames[3].odometry.x_m) /
                             static_cast<double>(frames.size() - 4);
  EXPECT_NEAR(per_frame_m, 0.05, 0.002);  // 0.5 m/s x 0.1 s
}

TEST(P2osRobotPty, NoAnswerThrowsNamingTheDevice) {
  auto pty = open_pty();  // nobody serves the master
  P2osRobotOptions o = fast_options();
  o.sync_attempts = 2;
  o.sync_reply_timeout = 100ms;
  try {
    P2osRobot robot(open_serial_port(pty->slave_path, 9600), o);
    FAIL() << "expected StreamError";
  } catch (const StreamError& e) {
    EXPECT_NE(std::string(e.what()).find(pty->slave_path), std::string::npos) << e.what();
  }
}

TEST(P2osRobotHandshake, PeerEchoingTheWrongPacketForeverTimesOut) {
  // A peer that answers every SYNC with a SYNC0 echo, forever: each packet is valid, none is
  // the SYNC1 the handshake waits for. The handshake must give up at handshake_timeout.
  auto [ours, theirs] = make_memory_pair();
  std::atomic<bool> stop{false};
  std::thread peer([&, link = theirs.get()] {
    std::uint8_t buf[64];
    while (!stop) {
      try {
        (void)link->read(buf, 100ms);
        link->write(p2os::encode_command(p2os::Command::kSync0));
      } catch (const StreamError&) {
        return;  // our end closed
      }
    }
  });
  P2osRobotOptions o;
  o.sync_reply_timeout = 300ms;
  o.sync_attempts = 1000000;  // only the overall timeout can end it
  o.handshake_timeout = 1500ms;
  const auto started = std::chrono::steady_clock::now();
  try {
    P2osRobot robot(std::move(ours), o);
    FAIL() << "expected StreamError";
  } catch (const StreamError& e) {
    EXPECT_NE(std::string(e.what()).find("no complete SYNC0-2 exchange"), std::string::npos)
        << e.what();
  }
  const auto took = std::chrono::steady_clock::now() - started;
  EXPECT_GE(took, 1400ms);
  EXPECT_LT(took, 2500ms);
  stop = true;
  peer.join();
}

TEST(P2osRobotPty, Sync2SubclassPicksTheRobotModel) {
  // p3dx-sh.p: the P3-DX ring (SonarUnit 3 at 166, 27 mm, 10°), 1 m/s in AMRISim's model.
  P2osServerOptions so;
  so.identity = {"dx", "Pioneer", "p3dx-sh"};
  PtyRobot served(so);
  served.start();
  P2osRobot robot(served.client(), fast_options());
  EXPECT_EQ(robot.identity().subclass, "p3dx-sh");
  ASSERT_EQ(robot.geometry().sonars.size(), 16u);
  EXPECT_DOUBLE_EQ(robot.geometry().sonars[3].x_m, 0.166);
  EXPECT_DOUBLE_EQ(robot.geometry().width_m, 0.425);
  EXPECT_DOUBLE_EQ(robot.geometry().max_speed_mps, 1.0);
  robot.shutdown();
}

TEST(P2osRobotPty, WrongSubclassIsRejected) {
  P2osServerOptions so;
  so.identity = {"jr", "Pioneer", "seekurjr"};  // a MobileRobots robot, but no Pioneer
  PtyRobot served(so);
  served.start();
  try {
    P2osRobot robot(served.client(), fast_options());
    FAIL() << "expected StreamError";
  } catch (const StreamError& e) {
    EXPECT_NE(std::string(e.what()).find("'seekurjr', not a known Pioneer"), std::string::npos)
        << e.what();
  }
}

TEST(SerialPort, RejectsUnsupportedBaud) {
  auto pty = open_pty();
  EXPECT_THROW(open_serial_port(pty->slave_path, 4800), std::invalid_argument);
  EXPECT_THROW(open_serial_port("/nonexistent/ttyX", 9600), StreamError);
  for (int baud : {9600, 19200, 38400, 57600, 115200}) {
    EXPECT_NO_THROW(open_serial_port(pty->slave_path, baud));
  }
}

TEST(SerialPort, NonTerminalPathIsBadInputAndLeftUntouched) {
  // `drive --port /dev/null` or a regular file was exit 1, "tcgetattr: Inappropriate ioctl",
  // as if a robot had not answered; it is a wrong argument (exit 2 in `drive`).
  EXPECT_THROW(open_serial_port("/dev/null", 9600), std::invalid_argument);
  const std::string path = ::testing::TempDir() + "cogmap_not_a_tty.txt";
  { std::ofstream(path) << "keep me\n"; }
  try {
    open_serial_port(path, 9600);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not a serial port"), std::string::npos) << e.what();
  }
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "keep me");
  std::remove(path.c_str());
}

TEST(TcpTransport, HugePortIsBadInputNotAnInternalError) {
  // std::stol threw std::out_of_range: `drive` reported an internal error (exit 1) and
  // `serve`, whose threads were running, died in std::terminate.
  EXPECT_THROW(connect_tcp("127.0.0.1:99999999999999999999", 100ms), std::invalid_argument);
  EXPECT_THROW(TcpListener("127.0.0.1:99999999999999999999"), std::invalid_argument);
  EXPECT_THROW(TcpListener("127.0.0.1:65536"), std::invalid_argument);
}

TEST(TcpTransport, ConnectsAndRejectsBadAddresses) {
  TcpListener listener("127.0.0.1:0");
  auto client = connect_tcp("127.0.0.1:" + std::to_string(listener.port()), 1000ms);
  auto server = listener.accept(1000ms);
  ASSERT_TRUE(server);
  const std::vector<std::uint8_t> ping = {1, 2, 3};
  client->write(ping);
  std::uint8_t buf[8];
  std::size_t got = 0;
  while (got < 3) got += server->read(std::span(buf + got, 8 - got), 1000ms);
  EXPECT_EQ(buf[2], 3);
  EXPECT_EQ(server->read(buf, 10ms), 0u);  // timeout, no data
  client.reset();
  EXPECT_THROW(server->read(buf, 1000ms), StreamClosed);
  EXPECT_THROW(connect_tcp("nohostport", 100ms), std::invalid_argument);
  EXPECT_THROW(connect_tcp("127.0.0.1:1", 500ms), StreamError);  // refused
}

// The server keeps streaming to a silent client while its link takes bytes; a pty whose
// client is gone (the slave still held open by us) must say so once its buffer fills, or the
// server's writes would time out and end `cogmap serve`.
TEST(Pty, UnreadMasterStopsAcceptingWritesAndRecovers) {
  auto pty = open_pty();
  const std::vector<std::uint8_t> sip(50, 0x55);
  std::size_t written = 0;
  while (pty->master->accepts_writes() && written < (16u << 20)) {
    pty->master->write(sip);
    written += sip.size();
  }
  EXPECT_FALSE(pty->master->accepts_writes()) << written << " bytes written";
  std::uint8_t buf[4096];
  pollfd p{pty->slave_fd, POLLIN, 0};
  while (::poll(&p, 1, 50) > 0 && ::read(pty->slave_fd, buf, sizeof buf) > 0) {
  }
  EXPECT_TRUE(pty->master->accepts_writes());
}

TEST(MemoryPair, ReadsTimeOutAndCloseIsSeen) {
  auto [a, b] = make_memory_pair();
  const std::vector<std::uint8_t> x = {9};
  a->write(x);
  std::uint8_t buf[4];
  EXPECT_EQ(b->read(buf, 10ms), 1u);
  EXPECT_EQ(b->read(buf, 10ms), 0u);
  a.reset();
  EXPECT_THROW(b->read(buf, 10ms), StreamClosed);
  EXPECT_THROW(b->write(x), StreamClosed);
}

}  // namespace
}  // namespace cogmap::hw
