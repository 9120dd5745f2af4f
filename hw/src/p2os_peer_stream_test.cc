// P2osRobot against scripted P2OS peers (scripted_p2os_peer.h) once the stream runs: packets
// interleaved, garbage, one-byte writes, a controller reset in the middle of a SIP, SIPs that
// never parse, no SIPs, sonar numbers beyond the model, range extremes and counter wraps, a
// flood, a peer closing mid-run.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "scripted_p2os_peer.h"

namespace cogmap::hw {
namespace {

using namespace testing;  // the scripted peers
using namespace std::chrono_literals;

// A P3-DX-style peer: 0x33 SIPs with the long tail and unknown trailing bytes, CONFIG (0x20),
// ENCODER (0x90) and IO (0xF0) packets between SIPs, garbage, a bad checksum every 7th SIP,
// and every write one byte at a time. Every good SIP must become a frame, in order.
TEST(P2osPeers, InterleavedPacketsGarbageAndOneByteWrites) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sync2_body = p2os::encode_sync2({"dx", "Pioneer", "p3dx-sh"});
  script.piece = 1;  // one byte a write, 1 ms apart: the driver reads them one by one
  script.piece_pause = 1ms;
  script.sip = [](std::uint64_t n) {
    Bytes b = sip_body(0x33, static_cast<std::uint16_t>(100 * n), 0, 0,
                       {{static_cast<std::uint8_t>(n % 16), 1500}});
    b.insert(b.end(), {0x11, 0x22, 0x33, 0x44});  // fields of newer firmware
    return b;
  };
  script.before_sip = [](std::uint64_t n) {
    Bytes out;
    const Bytes config = p2os::frame(Bytes{0x20, 'P', 'i', 'o', 'n', 'e', 'e', 'r', 0, 1, 2});
    const Bytes encoder = p2os::frame(Bytes{0x90, 1, 0, 0, 0, 2, 0, 0, 0});
    const Bytes io = p2os::frame(Bytes{0xF0, 4, 0, 0, 0, 0, 0, 0});
    for (const Bytes* p : {&config, &encoder, &io}) out.insert(out.end(), p->begin(), p->end());
    // Garbage: stray header bytes, counts 0, 1, 255, and a count of 5 that swallows the
    // start of the next packet.
    out.insert(out.end(), {0x00, 0xFA, 0x13, 0xFB, 0xFA, 0xFB, 0x00, 0xFA, 0xFB, 0x01, 0xFA, 0xFB,
                           0xFF, 0xFA, 0xFB, 0x05});
    if (n % 7 == 3) {  // a SIP whose checksum is wrong: dropped, the next one is found
      Bytes bad = p2os::frame(sip_body(0x33, 0, 0, 0, {}));
      bad.back() ^= 0x5A;
      out.insert(out.end(), bad.begin(), bad.end());
    }
    return out;
  };
  script.period = 100ms;
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobot robot(std::move(ours), quick_options());
  const auto frames = frames_for(robot, 1500ms);
  const P2osStats stats = robot.stats();
  robot.shutdown();
  ASSERT_GE(frames.size(), 5u);
  EXPECT_EQ(stats.bad_sips, 0u);
  EXPECT_GT(stats.dropped_bytes, 0u);
  for (std::size_t i = 1; i < frames.size(); ++i) {
    // 100 units of 1.0 mm (p3dx-sh) per SIP: no SIP lost, none out of order
    EXPECT_NEAR(frames[i].odometry.x_m - frames[i - 1].odometry.x_m, 0.1, 1e-9) << i;
    ASSERT_EQ(frames[i].sonar.size(), 1u);
    EXPECT_NEAR(frames[i].sonar[0].range_m, 1.5, 1e-9);
  }
}

// The controller resets in the middle of a SIP: the truncated SIP, then the reset packet, then
// silence until the next SYNC0; the counters restart at zero. The decoder used to wait for the
// truncated SIP's missing bytes, which never came, so the reset packet behind them was never
// read: the reconnection took the silence path, and a robot 2 m from its counter origin
// (inside the "plausible" distance) jumped back 2 m.
TEST(P2osPeers, ResetInTheMiddleOfASipIsStillSeen) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  std::atomic<bool> after_reset{false};
  std::atomic<std::uint64_t> reset_index{0};
  // 40 units of 1.32 mm a SIP: 2 m after 38 SIPs; after the reset the counters start over.
  script.sip = [&](std::uint64_t n) {
    const std::uint64_t k = after_reset ? n - reset_index : n;
    return sip_body(0x32, static_cast<std::uint16_t>(40 * k), 0, 0, {});
  };
  script.reset_at = [&](std::uint64_t n, ByteStream& link) {
    if (n != 40) return false;
    const Bytes sip = p2os::frame(sip_body(0x32, 40 * 40, 0, 0, {{1, 900}, {2, 900}}));
    link.write(std::span(sip).first(17));  // cut off mid-SIP
    link.write(p2os::frame(Bytes{p2os::kResetPacket}));
    reset_index = n + 1;
    after_reset = true;
    return true;
  };
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobot robot(std::move(ours), quick_options());
  const auto frames = frames_for(robot, 2500ms);
  const P2osStats stats = robot.stats();
  robot.shutdown();
  EXPECT_EQ(stats.resets, 1);
  EXPECT_EQ(stats.connections, 2);
  ASSERT_GE(frames.size(), 50u);
  for (std::size_t i = 1; i < frames.size(); ++i) {
    EXPECT_LT(std::abs(frames[i].odometry.x_m - frames[i - 1].odometry.x_m), 0.06) << i;
  }
  EXPECT_GT(frames.back().odometry.x_m, 2.1);  // kept counting on from 2.1 m
}

// Every SIP has a valid checksum but a layout this driver cannot read (it stops right after
// the sonar readings). The driver used to log each one and reconnect every silence_timeout
// for ever, with failure() empty, so `drive` wrote an empty run and exited 0. Now the
// connection ends with an error naming the field, the body offset and the stream offset.
TEST(P2osPeers, SipsThatNeverParseEndTheSessionWithTheReason) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sip = [](std::uint64_t) {
    Bytes b = sip_body(0x32, 0, 0, 0, {{0, 500}}, false);
    b.resize(b.size() - 5);  // no GRIP_STATE .. DIGOUT
    return b;
  };
  ScriptedPeer peer(std::move(theirs), script);
  std::vector<std::string> log;
  std::mutex log_mutex;
  P2osRobot robot(std::move(ours), quick_options(&log, &log_mutex));
  const auto started = std::chrono::steady_clock::now();
  EXPECT_FALSE(robot.next_frame().has_value());
  EXPECT_LT(std::chrono::steady_clock::now() - started, 1900ms);
  const std::string failure = robot.failure();
  EXPECT_NE(failure.find("GRIP_STATE"), std::string::npos) << failure;
  EXPECT_NE(failure.find("stream offset"), std::string::npos) << failure;
  const P2osStats stats = robot.stats();
  EXPECT_GE(stats.bad_sips, 10u);
  EXPECT_EQ(stats.sips, 0u);
  // Bad input (`drive` exit 2), not a lost link; the reason outlives shutdown.
  EXPECT_EQ(robot.failure_kind(), P2osFailureKind::kBadBytes) << failure;
  robot.shutdown();
  EXPECT_EQ(robot.failure_kind(), P2osFailureKind::kBadBytes);
  std::lock_guard lock(log_mutex);
  EXPECT_LE(log.size(), 16u);  // a bounded number of lines, not one per SIP
}

// A peer that completes every handshake but never sends a SIP (or only packets of types this
// driver does not read): each silence_timeout brought a reconnection that succeeded and
// cleared failure(), so when next_frame() gave up the session looked like a clean end, and
// `drive` exited 0 with an empty run.
TEST(P2osPeers, HandshakesWithoutSipsEndWithAFailure) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;  // no SIPs at all
  script.resync_when_open = true;
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobotOptions o = quick_options();
  o.silence_timeout = 400ms;
  o.frame_wait = 1500ms;
  P2osRobot robot(std::move(ours), o);
  EXPECT_FALSE(robot.next_frame().has_value());
  const std::string failure = robot.failure();
  EXPECT_NE(failure.find("no SIP in 1500 ms"), std::string::npos) << failure;
  EXPECT_GE(robot.stats().connections, 2);
  robot.shutdown();
  EXPECT_FALSE(robot.failure().empty());
}

// A PeopleBot-style peer with 32 transducers talking to a p2at geometry (16): the readings of
// 16-31 are dropped (counted), and the first one is reported once, with its stream offset.
TEST(P2osPeers, SonarNumbersBeyondTheModelAreCountedAndReportedOnce) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sip = [](std::uint64_t n) {
    std::vector<p2os::SipSonar> sonars;
    for (std::uint8_t i = 0; i < 32; ++i) sonars.push_back({i, static_cast<std::uint16_t>(n)});
    return sip_body(0x32, 0, 0, 0, sonars);
  };
  ScriptedPeer peer(std::move(theirs), script);
  std::vector<std::string> log;
  std::mutex log_mutex;
  P2osRobot robot(std::move(ours), quick_options(&log, &log_mutex));
  const auto frames = frames_for(robot, 300ms);
  const P2osStats stats = robot.stats();
  robot.shutdown();
  ASSERT_GE(frames.size(), 3u);
  for (const auto& f : frames) EXPECT_EQ(f.sonar.size(), 16u);
  EXPECT_EQ(stats.unknown_sonars, 16u * stats.sips);
  std::lock_guard lock(log_mutex);
  int reported = 0;
  for (const std::string& m : log) {
    if (m.find("sonar number 16") != std::string::npos) {
      ++reported;
      EXPECT_NE(m.find("stream offset"), std::string::npos) << m;
    }
  }
  EXPECT_EQ(reported, 1);
}

// Sonar ranges at the ends of the field: 0 stays a reading of 0 m (the mapper drops it as
// non-positive), 0xFFFF is "no echo" at the maximum range; odometry through the 15-bit wrap
// in both directions and the 12-bit heading wrap, with signed (16-bit) counters as some peers
// send them.
TEST(P2osPeers, RangeExtremesAndCounterWrapsBothWays) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  // x: 0x7FF0 upwards through 0x7FFF; y: 5 downwards through 0 (as 16-bit two's complement);
  // heading: 4090 upwards through 4095 -> 0.
  script.sip = [](std::uint64_t n) {
    const auto k = static_cast<int>(n);
    return sip_body(0x32, static_cast<std::uint16_t>(0x7FF0 + 4 * k),
                    static_cast<std::uint16_t>(5 - 2 * k), static_cast<std::int16_t>(4090 + k),
                    {{0, 0}, {1, 0xFFFF}});
  };
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobot robot(std::move(ours), quick_options());
  const auto frames = frames_for(robot, 500ms);
  robot.shutdown();
  ASSERT_GE(frames.size(), 10u);
  for (std::size_t i = 1; i < frames.size(); ++i) {
    EXPECT_NEAR(frames[i].odometry.x_m - frames[i - 1].odometry.x_m, 4 * 1.32e-3, 1e-9) << i;
    EXPECT_NEAR(frames[i].odometry.y_m - frames[i - 1].odometry.y_m, -2 * 1.32e-3, 1e-9) << i;
    EXPECT_NEAR(
        mapper::wrap_angle_rad(frames[i].odometry.theta_rad - frames[i - 1].odometry.theta_rad),
        2 * M_PI / 4096, 1e-9)
        << i;
    ASSERT_EQ(frames[i].sonar.size(), 2u);
    EXPECT_TRUE(frames[i].sonar[0].echo);
    EXPECT_EQ(frames[i].sonar[0].range_m, 0.0);
    EXPECT_FALSE(frames[i].sonar[1].echo);
    EXPECT_EQ(frames[i].sonar[1].range_m, robot.geometry().sonar_max_range_m);
  }
}

// A peer that floods SIPs as fast as the link takes them while nobody reads frames: the frame
// queue stays at its bound, the oldest dropped and counted.
TEST(P2osPeers, FloodingPeerKeepsTheQueueBounded) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.period = 0ms;
  script.sip = [](std::uint64_t n) {
    return sip_body(0x32, static_cast<std::uint16_t>(n & 0x7FFF), 0, 0, {{0, 100}});
  };
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobotOptions o = quick_options();
  o.max_queued_frames = 50;
  P2osRobot robot(std::move(ours), o);
  std::this_thread::sleep_for(600ms);
  const P2osStats stats = robot.stats();
  robot.shutdown();
  EXPECT_GT(stats.sips, 60u);
  EXPECT_GT(stats.dropped_frames, 0u);
  EXPECT_LE(stats.sips - stats.dropped_frames, 50u);  // nobody read: what is queued is capped
}

// The peer closes the connection mid-run: next_frame() ends promptly and failure() says why.
TEST(P2osPeers, PeerClosingMidRunEndsTheSession) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sip = [](std::uint64_t) { return sip_body(0x32, 0, 0, 0, {}); };
  auto peer = std::make_unique<ScriptedPeer>(std::move(theirs), script);
  P2osRobot robot(std::move(ours), quick_options());
  EXPECT_GE(frames_for(robot, 200ms).size(), 2u);
  peer.reset();  // destroys the robot end
  const auto started = std::chrono::steady_clock::now();
  while (robot.next_frame()) {
  }
  EXPECT_LT(std::chrono::steady_clock::now() - started, 1500ms);
  EXPECT_NE(robot.failure().find("peer closed"), std::string::npos) << robot.failure();
}

}  // namespace
}  // namespace cogmap::hw
