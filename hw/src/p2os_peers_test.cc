// P2osRobot against scripted P2OS peers (scripted_p2os_peer.h) at the handshake and the SIP's
// type: other SIP type bytes, a link that echoes, loopback, odd or hostile SYNC2 replies.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "scripted_p2os_peer.h"

namespace cogmap::hw {
namespace {

using namespace testing;  // the scripted peers
using namespace std::chrono_literals;

// Player's and ROS's p2os drivers take every type 0x30-0x34 as the standard SIP ("0x3S", S the
// motor status); a peer that sends 0x30, 0x31 or 0x34 gave no frames at all and was
// "reconnected" every silence_timeout for ever.
TEST(P2osPeers, SipTypeBytes0x30To0x34AreStandardSips) {
  for (std::uint8_t type : {0x30, 0x31, 0x34}) {
    auto [ours, theirs] = make_memory_pair();
    PeerScript script;
    script.sip = [type](std::uint64_t n) {
      return sip_body(type, static_cast<std::uint16_t>(10 * n), 0, 0, {{3, 1000}});
    };
    ScriptedPeer peer(std::move(theirs), script);
    P2osRobot robot(std::move(ours), quick_options());
    const auto frames = frames_for(robot, 400ms);
    const P2osStats stats = robot.stats();
    robot.shutdown();
    ASSERT_GE(frames.size(), 5u) << "type 0x" << std::hex << int(type);
    EXPECT_EQ(stats.connections, 1);
    ASSERT_EQ(frames.back().sonar.size(), 1u);
    EXPECT_EQ(frames.back().sonar[0].index, 3);
    EXPECT_NEAR(frames.back().sonar[0].range_m, 0.268, 1e-9);
  }
}

// A link that echoes every byte we send: our own SYNC0 and SYNC1 come back first (harmless,
// the robot's own echoes follow), but our own SYNC2 came back as a bare type-2 packet with no
// name strings, which restarted the handshake at SYNC0 every time: it never connected.
TEST(P2osPeers, EchoingLinkStillConnects) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sip = [](std::uint64_t n) {
    return sip_body(0x32, static_cast<std::uint16_t>(n), 0, 0, {{1, 2000}});
  };
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobot robot(std::make_unique<EchoingLink>(std::move(ours)), quick_options());
  EXPECT_EQ(robot.identity().subclass, "p2at");
  const auto frames = frames_for(robot, 400ms);
  robot.shutdown();
  EXPECT_GE(frames.size(), 5u);
}

// Nobody at the far end of an echoing link: every SYNC comes back as itself. The handshake
// fails, and the error says what came back instead of only "no complete exchange".
TEST(P2osPeers, LoopbackWithoutRobotFailsNamingTheEcho) {
  auto [ours, theirs] = make_memory_pair();
  P2osRobotOptions o = quick_options();
  o.sync_attempts = 2;
  o.sync_reply_timeout = 100ms;
  try {
    P2osRobot robot(std::make_unique<EchoingLink>(std::move(ours)), o);
    FAIL() << "expected StreamError";
  } catch (const StreamError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no complete SYNC0-2 exchange"), std::string::npos) << what;
    EXPECT_NE(what.find("echo"), std::string::npos) << what;
    EXPECT_NE(what.find("stream offset"), std::string::npos) << what;
  }
}

// A SYNC2 reply in an odd layout (the name missing, only class and subclass): the handshake
// fails, and the final error names what was wrong and where, not just the attempt count.
TEST(P2osPeers, MalformedSync2ReplyIsNamedInTheError) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sync2_body = {2, 'P', 'i', 'o', 'n', 'e', 'e', 'r', 0, 'p', '2', 'a', 't', 0};
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobotOptions o = quick_options();
  o.sync_attempts = 2;
  try {
    P2osRobot robot(std::move(ours), o);
    FAIL() << "expected StreamError";
  } catch (const StreamError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("2 of 3 strings"), std::string::npos) << what;
    EXPECT_NE(what.find("stream offset"), std::string::npos) << what;
  }
}

// A SYNC2 reply whose strings hold terminal control bytes: the refusal names them escaped, so
// a peer cannot clear or recolour the user's terminal through our error message.
TEST(P2osPeers, Sync2StringsAreEscapedInMessages) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sync2_body = p2os::encode_sync2({"\x1b[2J", "Pioneer", "p2at\x1b[31m\x07"});
  ScriptedPeer peer(std::move(theirs), script);
  try {
    P2osRobot robot(std::move(ours), quick_options());
    FAIL() << "expected StreamError";
  } catch (const StreamError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\x1b'), std::string::npos) << what;
    EXPECT_EQ(what.find('\x07'), std::string::npos) << what;
    EXPECT_NE(what.find("robot '\\x1b[2J' is a Pioneer 'p2at\\x1b[31m\\x07'"), std::string::npos)
        << what;
  }
}

// A SYNC2 reply with odd but usable layouts: no final NUL, extra strings after the subclass,
// an empty name, upper case. All connect with the right model.
TEST(P2osPeers, Sync2LayoutsThatStillNameTheRobot) {
  const std::vector<Bytes> replies = {
      {2, 'a', 0, 'P', 'i', 'o', 'n', 'e', 'e', 'r', 0, 'p', '3', 'd', 'x'},
      {2, 'a', 0, 'P', 'i', 'o', 'n', 'e', 'e', 'r', 0, 'p', '3', 'd', 'x', 0, 'x', 0, 'y', 0},
      {2, 0, 'P', 'i', 'o', 'n', 'e', 'e', 'r', 0, 'P', '3', 'D', 'X', 0},
  };
  for (const Bytes& reply : replies) {
    auto [ours, theirs] = make_memory_pair();
    PeerScript script;
    script.sync2_body = reply;
    script.sip = [](std::uint64_t) { return sip_body(0x32, 0, 0, 0, {}); };
    ScriptedPeer peer(std::move(theirs), script);
    P2osRobot robot(std::move(ours), quick_options());
    EXPECT_EQ(robot.geometry().max_speed_mps, 1.0);  // the p3dx model
    EXPECT_GE(frames_for(robot, 200ms).size(), 2u);
    robot.shutdown();
  }
}

// SYNC replies that come late (a slow radio modem or network-serial bridge), each 200 ms after
// its SYNC, within the 300 ms this test allows a step: the handshake still completes at once.
TEST(P2osPeers, SlowSyncRepliesWithinTheTimeoutConnect) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sync_delay = 200ms;
  script.sip = [](std::uint64_t n) {
    return sip_body(0x32, static_cast<std::uint16_t>(n), 0, 0, {{2, 700}});
  };
  ScriptedPeer peer(std::move(theirs), script);
  const auto started = std::chrono::steady_clock::now();
  P2osRobot robot(std::move(ours), quick_options());
  EXPECT_LT(std::chrono::steady_clock::now() - started, 1000ms);  // one round, no restart
  EXPECT_GE(frames_for(robot, 300ms).size(), 3u);
  EXPECT_EQ(robot.stats().connections, 1);
  robot.shutdown();
}

// SYNC replies 800 ms after each SYNC (a slow radio modem or network-serial bridge), with the
// options a real robot gets: ARIA waits 1 s for each echo and connects; our 500 ms restarted
// at SYNC0 every time, the stale echoes piled up and the handshake failed. Now it connects in
// its first round.
TEST(P2osPeers, SyncRepliesAfter800MsConnectWithDefaults) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sync_delay = 800ms;
  script.sip = [](std::uint64_t n) {
    return sip_body(0x32, static_cast<std::uint16_t>(n), 0, 0, {{2, 700}});
  };
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobot robot(std::move(ours), P2osRobotOptions{});
  EXPECT_EQ(robot.identity().subclass, "p2at");
  EXPECT_EQ(peer.sync0s(), 1);  // one round: no SYNC timed out
  EXPECT_GE(frames_for(robot, 300ms).size(), 3u);
  EXPECT_EQ(robot.stats().connections, 1);
  robot.shutdown();
}

// Nothing answers (a port with no robot behind it): the handshake fails with the same error
// as before, after ARIA's 6 unanswered SYNCs of 1 s each, far inside handshake_timeout.
TEST(P2osPeers, SilentPortFailsAfterSixSyncsOfOneSecond) {
  auto [ours, theirs] = make_memory_pair();  // `theirs` stays open and never answers
  const auto started = std::chrono::steady_clock::now();
  try {
    P2osRobot robot(std::move(ours), P2osRobotOptions{});
    FAIL() << "expected P2osHandshakeError";
  } catch (const P2osHandshakeError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.kind(), P2osFailureKind::kLink) << what;
    EXPECT_NE(what.find("P2OS handshake failed: no complete SYNC0-2 exchange in 6 attempts"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("last: no reply to SYNC0 within 1000 ms"), std::string::npos) << what;
  }
  const auto took = std::chrono::steady_clock::now() - started;
  EXPECT_GE(took, 5900ms);
  EXPECT_LT(took, 7500ms);
}

// A silent port under a short overall bound (`drive --duration 3`): the attempt that runs into
// the bound is the last. The wait left before it was truncated to whole milliseconds, so in
// its last millisecond every remaining attempt sent a SYNC0 and waited for nothing, and "in
// 11 attempts" was reported for three.
TEST(P2osPeers, HandshakeCutByItsBoundCountsOnlyRealAttempts) {
  auto [ours, theirs] = make_memory_pair();
  P2osRobotOptions o = quick_options();
  o.sync_reply_timeout = 200ms;
  o.silent_sync_attempts = 100;
  o.handshake_timeout = 500ms;  // 200 + 200 + 100 ms
  try {
    P2osRobot robot(std::move(ours), o);
    FAIL() << "expected P2osHandshakeError";
  } catch (const P2osHandshakeError& e) {
    EXPECT_NE(std::string(e.what()).find("no complete SYNC0-2 exchange in 3 attempts"),
              std::string::npos)
        << e.what();
  }
}

// A peer that echoes SYNC0 but never SYNC1 is there, just not answering right: it gets all
// sync_attempts rounds (ARIA allows 10 unanswered SYNCs once one was answered), where a
// silent port gets silent_sync_attempts.
TEST(P2osPeers, AnsweringPeerGetsAllAttempts) {
  auto [ours, theirs] = make_memory_pair();
  std::atomic<bool> stop{false};
  std::thread peer([&stop, link = theirs.get()] {
    p2os::PacketDecoder decoder;
    std::uint8_t buf[64];
    try {
      while (!stop) {
        decoder.feed({buf, link->read(buf, 5ms)});
        while (auto p = decoder.next()) {
          if (p->type() == 0 && p->body.size() == 1) {
            link->write(p2os::encode_command(p2os::Command::kSync0));
          }
        }
      }
    } catch (const StreamError&) {
      // our end closed
    }
  });
  P2osRobotOptions o = quick_options();
  o.sync_reply_timeout = 100ms;
  try {
    P2osRobot robot(std::move(ours), o);
    ADD_FAILURE() << "expected P2osHandshakeError";
  } catch (const P2osHandshakeError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no complete SYNC0-2 exchange in 11 attempts"), std::string::npos) << what;
    EXPECT_NE(what.find("last: no reply to SYNC1 within 100 ms"), std::string::npos) << what;
  }
  stop = true;
  peer.join();
}

// A robot an earlier client left open, streaming older P2OS SIPs (no BATTERYX10 ... tail),
// whose firmware echoes SYNC0 even while open and goes on streaming until CLOSE: the echo
// must not be taken for the start of a handshake with SIPs still coming. The SIP is seen,
// CLOSE sent, and the second handshake connects.
TEST(P2osPeers, LeftOpenRobotThatEchoesSync0WhileStreaming) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.start_open = true;
  script.echo_sync0_while_open = true;
  script.sip = [](std::uint64_t n) {
    return sip_body(0x33, static_cast<std::uint16_t>(5 * n), 0, 0, {{4, 1000}}, false);
  };
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobot robot(std::move(ours), quick_options());
  const auto frames = frames_for(robot, 300ms);
  const P2osStats stats = robot.stats();
  robot.shutdown();
  EXPECT_GE(stats.left_open_recoveries, 1);
  EXPECT_EQ(stats.connections, 1);
  EXPECT_EQ(stats.bad_sips, 0u);
  ASSERT_GE(frames.size(), 3u);
  ASSERT_EQ(frames.back().sonar.size(), 1u);
  EXPECT_NEAR(frames.back().sonar[0].range_m, 0.268, 1e-9);
  EXPECT_EQ(peer.opens(), 1);
}

}  // namespace
}  // namespace cogmap::hw
