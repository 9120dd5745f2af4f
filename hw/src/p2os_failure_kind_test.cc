// P2osRobot::failure_kind() and P2osHandshakeError::kind(): why a session ended, which `drive`
// turns into its exit code (bytes that never decode: 2; silence, a closed link, an unsupported
// robot: 1). Each case is a peer that fails one way (scripted_p2os_peer.h, or a raw babbler).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "scripted_p2os_peer.h"

namespace cogmap::hw {
namespace {

using namespace testing;  // the scripted peers
using namespace std::chrono_literals;

// The robot end writes `chunk` every `period`, whatever it is sent, `chunks` times (-1: for
// ever): a GPS on the port, a robot at another baud rate, a line that picks up noise.
class BabblingPeer {
 public:
  BabblingPeer(std::unique_ptr<ByteStream> link, Bytes chunk, std::chrono::milliseconds period,
               int chunks = -1)
      : link_(std::move(link)) {
    thread_ = std::thread([this, chunk, period, chunks]() mutable {
      std::uint8_t buf[256];
      try {
        while (!stop_) {
          (void)link_->read(buf, period);  // what the client sends is ignored
          if (chunks != 0) {
            link_->write(chunk);
            if (chunks > 0) --chunks;
          }
        }
      } catch (const StreamError&) {
        // the client end is gone
      }
    });
  }
  ~BabblingPeer() {
    stop_ = true;
    thread_.join();
  }

 private:
  std::unique_ptr<ByteStream> link_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// What the robot end of a MutableLink does with what the peer writes.
enum class LinkMode { kPass, kMute /* a cable pulled out */, kGarble /* noise, as long */ };

class MutableLink final : public ByteStream {
 public:
  MutableLink(std::unique_ptr<ByteStream> inner, std::atomic<LinkMode>& mode)
      : inner_(std::move(inner)), mode_(mode) {}
  void write(std::span<const std::uint8_t> bytes) override {
    if (mode_ == LinkMode::kPass) inner_->write(bytes);
    if (mode_ == LinkMode::kGarble) inner_->write(Bytes(bytes.size(), 0x55));  // no header
  }
  std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
    return inner_->read(buffer, timeout);
  }
  std::string name() const override { return inner_->name(); }

 private:
  std::unique_ptr<ByteStream> inner_;
  std::atomic<LinkMode>& mode_;
};

Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }

// A good SIP whose X counts the SIPs sent: a robot that works, until a case breaks its link.
Bytes counting_sip(std::uint64_t n) {
  return sip_body(0x32, static_cast<std::uint16_t>(n), 0, 0, {{1, 1000}});
}

// That robot behind a link the test can cut (kMute) or garble later: `robot_end` goes to the
// P2osRobot, `mode` breaks the link. Declared before the robot, so it outlives it.
struct BreakableRobot {
  std::atomic<LinkMode> mode{LinkMode::kPass};
  std::unique_ptr<ByteStream> robot_end;
  std::unique_ptr<ScriptedPeer> peer;
  BreakableRobot() {
    auto [ours, theirs] = make_memory_pair();
    robot_end = std::move(ours);
    PeerScript script;
    script.sip = counting_sip;
    peer = std::make_unique<ScriptedPeer>(std::make_unique<MutableLink>(std::move(theirs), mode),
                                          script);
  }
};

// A short handshake: every case below fails it within about a second.
P2osRobotOptions short_handshake() {
  P2osRobotOptions o = quick_options();
  o.sync_attempts = 3;
  o.sync_reply_timeout = 150ms;
  return o;
}

// Builds a P2osRobot that must fail its handshake; returns the error's kind and message.
std::pair<P2osFailureKind, std::string> handshake_failure(std::unique_ptr<ByteStream> link,
                                                          P2osRobotOptions o) {
  try {
    P2osRobot robot(std::move(link), o);
  } catch (const P2osHandshakeError& e) {
    return {e.kind(), e.what()};
  }
  ADD_FAILURE() << "the handshake succeeded";
  return {P2osFailureKind::kNone, ""};
}

// A GPS talking NMEA at the port, and a robot heard at the wrong baud rate (header-like bytes,
// bad counts and checksums): bytes arrive, nothing decodes. Bad input, with the offsets.
TEST(P2osFailureKind, GarbageOnlyHandshakeIsBadBytes) {
  const std::vector<Bytes> garbage = {
      text("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n"),
      {0xFA, 0xFB, 0x05, 0x00, 0x33, 0x12, 0x34, 0x56, 0xFA, 0xFB, 0xFA, 0x02, 0xFE, 0x80}};
  for (const Bytes& chunk : garbage) {
    auto [ours, theirs] = make_memory_pair();
    BabblingPeer peer(std::move(theirs), chunk, 30ms);
    const auto [kind, what] = handshake_failure(std::move(ours), short_handshake());
    EXPECT_EQ(kind, P2osFailureKind::kBadBytes) << what;
    EXPECT_NE(what.find("only bytes that do not decode as P2OS came back"), std::string::npos)
        << what;
    EXPECT_NE(what.find("none formed a packet"), std::string::npos) << what;
    EXPECT_NE(what.find("stream offset"), std::string::npos) << what;
  }
}

// Noise once, then nothing: still only undecodable bytes came back (silence counts for
// neither side), so it is bad input, and the message names the noise, not the silence.
TEST(P2osFailureKind, NoiseThenSilenceIsBadBytes) {
  auto [ours, theirs] = make_memory_pair();
  BabblingPeer peer(std::move(theirs), text("\x01\x02\x03"), 30ms, 1);
  const auto [kind, what] = handshake_failure(std::move(ours), short_handshake());
  EXPECT_EQ(kind, P2osFailureKind::kBadBytes) << what;
  EXPECT_NE(what.find("3 bytes arrived (stream offsets 0-2)"), std::string::npos) << what;
}

// SYNC0 and SYNC1 echoed, but every SYNC2 reply unreadable: the handshake was answered with
// garbage.
TEST(P2osFailureKind, UnreadableSync2ReplyIsBadBytes) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sync2_body = {2, 'P', 'i', 'o', 'n', 'e', 'e', 'r', 0};  // one string of three
  ScriptedPeer peer(std::move(theirs), script);
  const auto [kind, what] = handshake_failure(std::move(ours), short_handshake());
  EXPECT_EQ(kind, P2osFailureKind::kBadBytes) << what;
  EXPECT_NE(what.find("bad SYNC2 reply at stream offset"), std::string::npos) << what;
}

// Nobody answers: a lost link, not bad input.
TEST(P2osFailureKind, SilentPeerIsALink) {
  auto [ours, theirs] = make_memory_pair();
  const auto [kind, what] = handshake_failure(std::move(ours), short_handshake());
  EXPECT_EQ(kind, P2osFailureKind::kLink) << what;
  EXPECT_NE(what.find("no reply to SYNC0"), std::string::npos) << what;
}

// Garbage, but also valid packets that are not the reply (a peer that speaks P2OS, wrongly):
// not only undecodable bytes came back, so it stays a failed link.
TEST(P2osFailureKind, GarbageWithValidPacketsIsALink) {
  auto [ours, theirs] = make_memory_pair();
  Bytes chunk = text("noise");
  const Bytes sync1 = p2os::encode_command(p2os::Command::kSync1);  // never what step 0 waits for
  chunk.insert(chunk.end(), sync1.begin(), sync1.end());
  BabblingPeer peer(std::move(theirs), chunk, 30ms);
  const auto [kind, what] = handshake_failure(std::move(ours), short_handshake());
  EXPECT_EQ(kind, P2osFailureKind::kLink) << what;
}

TEST(P2osFailureKind, UnknownSubclassIsUnsupportedRobot) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sync2_body = p2os::encode_sync2({"jr", "Pioneer", "seekurjr"});
  ScriptedPeer peer(std::move(theirs), script);
  const auto [kind, what] = handshake_failure(std::move(ours), short_handshake());
  EXPECT_EQ(kind, P2osFailureKind::kUnsupportedRobot) << what;
}

// The link already closed when the handshake starts: StreamClosed, which `drive` reports as a
// failed run; never a P2osHandshakeError of kind kBadBytes.
TEST(P2osFailureKind, ClosedLinkDuringHandshakeIsStreamClosed) {
  auto [ours, theirs] = make_memory_pair();
  theirs.reset();
  try {
    P2osRobot robot(std::move(ours), short_handshake());
    FAIL() << "the handshake succeeded";
  } catch (const P2osHandshakeError& e) {
    FAIL() << "expected StreamClosed, got a handshake error: " << e.what();
  } catch (const StreamClosed&) {
  }
}

// A clean session ended by shutdown(): no failure at all.
TEST(P2osFailureKind, CleanShutdownIsNone) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sip = counting_sip;
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobot robot(std::move(ours), quick_options());
  EXPECT_GE(frames_for(robot, 200ms).size(), 2u);
  EXPECT_EQ(robot.failure_kind(), P2osFailureKind::kNone);
  robot.shutdown();
  EXPECT_EQ(robot.failure_kind(), P2osFailureKind::kNone);
}

// Every handshake succeeds, but every SIP after it has a wrong checksum: no SIP ever decodes
// while bytes keep coming in their place. Bad input, naming the offset of the last discard.
TEST(P2osFailureKind, SipsWithBadChecksumsAreBadBytes) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sip = [](std::uint64_t) { return sip_body(0x32, 0, 0, 0, {{0, 500}}); };
  script.bad_sip_checksum = true;
  script.resync_when_open = true;
  ScriptedPeer peer(std::move(theirs), script);
  P2osRobotOptions o = quick_options();
  o.silence_timeout = 400ms;
  o.frame_wait = 1500ms;
  P2osRobot robot(std::move(ours), o);
  EXPECT_FALSE(robot.next_frame().has_value());
  const std::string failure = robot.failure();
  EXPECT_EQ(robot.failure_kind(), P2osFailureKind::kBadBytes) << failure;
  EXPECT_NE(failure.find("stream offset"), std::string::npos) << failure;
  EXPECT_EQ(robot.stats().sips, 0u);
  EXPECT_GT(robot.stats().dropped_bytes, 0u);
}

// A robot that sent good SIPs and then fell silent for good: a lost link.
TEST(P2osFailureKind, PeerFallingSilentIsALink) {
  BreakableRobot peer;
  P2osRobot robot(std::move(peer.robot_end), quick_options());
  EXPECT_GE(frames_for(robot, 200ms).size(), 2u);
  peer.mode = LinkMode::kMute;
  while (robot.next_frame()) {
  }
  EXPECT_EQ(robot.failure_kind(), P2osFailureKind::kLink) << robot.failure();
}

// Good SIPs, then only noise: the reconnection's handshakes get nothing but undecodable bytes
// and give up. Bad input, and the message still names the offsets.
TEST(P2osFailureKind, ReconnectionThatGetsOnlyNoiseIsBadBytes) {
  BreakableRobot peer;
  P2osRobotOptions o = short_handshake();
  o.silence_timeout = 400ms;
  o.reconnect_give_up = 1000ms;
  o.frame_wait = 10000ms;  // the reconnection gives up first
  P2osRobot robot(std::move(peer.robot_end), o);
  EXPECT_GE(frames_for(robot, 200ms).size(), 2u);
  peer.mode = LinkMode::kGarble;
  while (robot.next_frame()) {
  }
  const std::string failure = robot.failure();
  EXPECT_EQ(robot.failure_kind(), P2osFailureKind::kBadBytes) << failure;
  EXPECT_NE(failure.find("reconnection gave up"), std::string::npos) << failure;
  EXPECT_NE(failure.find("none formed a packet"), std::string::npos) << failure;
}

// A robot that falls silent mid-run: the reconnection gives up at reconnect_give_up, not a
// whole handshake_timeout later (a handshake started just before the give-up time used to run
// to its own end: up to 30 s + 30 s with the defaults).
TEST(P2osFailureKind, ReconnectionEndsAtItsGiveUpTime) {
  BreakableRobot peer;
  P2osRobotOptions o = quick_options();
  o.silence_timeout = 300ms;
  o.sync_reply_timeout = 500ms;
  o.sync_attempts = o.silent_sync_attempts = 20;  // a silent handshake: 10 s ...
  o.handshake_timeout = 6000ms;                   // ... cut to 6 s by its own bound
  o.reconnect_give_up = 1000ms;
  o.frame_wait = 20000ms;  // the reconnection gives up first
  P2osRobot robot(std::move(peer.robot_end), o);
  EXPECT_GE(frames_for(robot, 200ms).size(), 2u);
  peer.mode = LinkMode::kMute;
  const auto muted = std::chrono::steady_clock::now();
  while (robot.next_frame()) {
  }
  const auto took = std::chrono::steady_clock::now() - muted;
  // silence_timeout + reconnect_give_up = 1.3 s; before, 0.3 + 6 s.
  EXPECT_LT(took, 3000ms);
  EXPECT_GE(took, 1200ms);
  EXPECT_NE(robot.failure().find("reconnection gave up"), std::string::npos) << robot.failure();
  EXPECT_NE(robot.failure().find("ended at the reconnection's give-up time"), std::string::npos)
      << robot.failure();
  EXPECT_EQ(robot.failure_kind(), P2osFailureKind::kLink) << robot.failure();
}

// The peer closes the connection mid-run: a lost link.
TEST(P2osFailureKind, PeerClosingMidRunIsALink) {
  auto [ours, theirs] = make_memory_pair();
  PeerScript script;
  script.sip = [](std::uint64_t) { return sip_body(0x32, 0, 0, 0, {}); };
  auto peer = std::make_unique<ScriptedPeer>(std::move(theirs), script);
  P2osRobot robot(std::move(ours), quick_options());
  EXPECT_GE(frames_for(robot, 200ms).size(), 2u);
  peer.reset();
  while (robot.next_frame()) {
  }
  EXPECT_EQ(robot.failure_kind(), P2osFailureKind::kLink) << robot.failure();
}

}  // namespace
}  // namespace cogmap::hw
