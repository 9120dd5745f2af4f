// The robot side alone, over an in-memory link: sync replies, command handling, SIP content
// and the watchdog.
#include "cogmap/hw/p2os_server.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string_view>
#include <thread>

#include "p2os_served.h"

namespace cogmap::hw {
namespace {

using namespace std::chrono_literals;
using p2os::Command;

using testing::await;
using testing::Served;
using testing::types_for;

TEST(P2osServer, SyncOutOfOrderIsNotAnswered) {
  Served s;
  s.client->write(p2os::encode_command(Command::kSync2));
  EXPECT_FALSE(await(*s.client, s.decoder, 2).has_value());
  EXPECT_EQ(s.server->stats().syncs, 0u);
}

TEST(P2osServer, SipsCarryPoseSonarAndMotionFlags) {
  Served s;
  s.open();
  s.client->write(p2os::encode_command(Command::kVel, 400));
  s.client->write(p2os::encode_command(Command::kRVel, -20));
  std::optional<p2os::Packet> packet;
  for (int i = 0; i < 4; ++i) packet = await(*s.client, s.decoder, p2os::kSipMoving);
  ASSERT_TRUE(packet);  // the fourth moving SIP: the body has moved by now
  const p2os::Sip sip = p2os::decode_sip(packet->body);
  EXPECT_TRUE(sip.motors_enabled());
  EXPECT_EQ(sip.sonars.size(), 4u);
  EXPECT_EQ(*sip.rot_vel, -200);  // 0.1 deg/s units
  // Wheel speeds over the odometry track (2 / 0.0034 = 588 mm), as the encoder counts: 0.4 m/s
  // -/+ 20°/s x 0.294 m = 102.7 mm/s (over the physical 0.394 m it was 68.8: 1.49 x too few).
  EXPECT_EQ(sip.l_vel, 503);
  EXPECT_EQ(sip.r_vel, 297);
  EXPECT_GT(sip.x_pos, 0);
  EXPECT_NEAR(s.body.current().v_mps, 0.4, 1e-12);
  EXPECT_NEAR(s.body.current().w_radps, -20 * M_PI / 180, 1e-12);
}

TEST(P2osServer, Vel2SetsWheelSpeeds) {
  Served s;
  s.open();
  std::this_thread::sleep_for(100ms);
  // Left +10 (0.2 m/s) in the high byte, right +15 (0.3 m/s) in the low byte.
  s.client->write(p2os::encode_command(Command::kVel2, (10 << 8) | 15));
  std::this_thread::sleep_for(150ms);
  EXPECT_NEAR(s.body.current().v_mps, 0.25, 1e-12);
  // Over the p2at's odometry track, 2 / DiffConvFactor (0.0034): 100 mm/s x 0.0017 rad/mm.
  EXPECT_NEAR(s.body.current().w_radps, 0.17, 1e-12);
  // Negative left wheel: -5 (0xFB) left, +5 right: turn in place.
  s.client->write(p2os::encode_command(Command::kVel2, (0xFB << 8) | 5));
  std::this_thread::sleep_for(150ms);
  EXPECT_NEAR(s.body.current().v_mps, 0.0, 1e-12);
  EXPECT_NEAR(s.body.current().w_radps, 0.34, 1e-12);
}

TEST(P2osServer, MotionIgnoredUntilMotorsEnabled) {
  Served s;
  s.client->write(p2os::encode_command(Command::kSync0));
  await(*s.client, s.decoder, 0);
  s.client->write(p2os::encode_command(Command::kSync1));
  await(*s.client, s.decoder, 1);
  s.client->write(p2os::encode_command(Command::kSync2));
  await(*s.client, s.decoder, 2);
  s.client->write(p2os::encode_command(Command::kOpen));
  s.client->write(p2os::encode_command(Command::kVel, 300));
  std::this_thread::sleep_for(200ms);
  EXPECT_EQ(s.body.current().v_mps, 0.0);
}

TEST(P2osServer, WatchdogStopsAfterTwoSecondsOfSilence) {
  Served s;
  s.open();
  s.client->write(p2os::encode_command(Command::kVel, 300));
  std::this_thread::sleep_for(1000ms);
  EXPECT_NEAR(s.body.current().v_mps, 0.3, 1e-12);  // still within the watchdog time
  std::this_thread::sleep_for(1800ms);
  EXPECT_EQ(s.body.current().v_mps, 0.0);
  EXPECT_EQ(s.server->stats().watchdog_stops, 1u);
}

TEST(P2osServer, CloseStopsSipsAndResetSendsFF) {
  Served s;
  s.open();
  ASSERT_TRUE(await(*s.client, s.decoder, p2os::kSipStopped));
  s.server->request_reset();
  ASSERT_TRUE(await(*s.client, s.decoder, p2os::kResetPacket));
  // After the reset the robot is closed: no more SIPs until a new handshake.
  std::this_thread::sleep_for(150ms);
  while (s.decoder.next()) {
  }
  std::uint8_t buf[512];
  std::size_t got = 0;
  for (int i = 0; i < 5; ++i) got += s.client->read(buf, 50ms);
  EXPECT_EQ(got, 0u);
}

}  // namespace
}  // namespace cogmap::hw

namespace cogmap::hw {
namespace {

TEST(P2osServer, SilentOpenClientIsDroppedAfterClientTimeout) {
  P2osServerOptions o;
  o.client_timeout = 600ms;
  Served s(o);
  s.open();
  ASSERT_TRUE(await(*s.client, s.decoder, p2os::kSipStopped));
  s.link->backed_up = true;  // the client crashed: nobody reads, the link's buffer fills
  std::this_thread::sleep_for(1000ms);
  EXPECT_EQ(s.server->stats().client_timeouts, 1u);
  while (s.decoder.next()) {
  }
  std::uint8_t buf[512];
  while (s.client->read(buf, 1ms) > 0) {
  }
  std::size_t got = 0;
  for (int i = 0; i < 5; ++i) got += s.client->read(buf, 50ms);
  EXPECT_EQ(got, 0u);  // no SIPs into a link nobody reads
  s.link->backed_up = false;
  s.open();  // a new client can sync again
  EXPECT_TRUE(await(*s.client, s.decoder, p2os::kSipStopped));
}

// ROS's and Player's p2os send no command while idle (their `pulse` is off by default), yet
// block reading the next SIP. The server closed such a client after client_timeout of
// silence and stopped its SIPs, and the p2os node hung in its read for good. A silent client
// that still reads keeps its SIPs, as on a real controller (only the 2 s watchdog stops it).
TEST(P2osServer, SilentClientThatStillReadsKeepsItsSips) {
  P2osServerOptions o;
  o.client_timeout = 300ms;
  o.cycle = 20ms;
  Served s(o);
  s.open();
  ASSERT_TRUE(await(*s.client, s.decoder, p2os::kSipStopped));
  std::this_thread::sleep_for(700ms);  // well past client_timeout, reading nothing meanwhile
  std::uint64_t sips = 0;
  const auto end = std::chrono::steady_clock::now() + 300ms;
  std::uint8_t buf[512];
  while (std::chrono::steady_clock::now() < end) {
    s.decoder.feed({buf, s.client->read(buf, 20ms)});
    while (auto p = s.decoder.next()) sips += p2os::is_sip(p->type()) ? 1 : 0;
  }
  EXPECT_EQ(s.server->stats().client_timeouts, 0u);
  EXPECT_GE(sips, 40u);  // the 35 of the silent 700 ms, still queued, and the new ones
}

// A body whose frames carry 100 readings each: what the simulator reports after a client's
// SONAR_CYCLE 2 (each array fires a disc every 2 ms, 50 per array in a 100 ms cycle). The SIP
// of 100 readings needed a 330-byte packet; frame() threw std::invalid_argument out of run()
// and `cogmap serve` exited 2 on a valid client command. A P2OS SIP carries each transducer's
// newest reading; so does the server now.
class ChattyBody final : public mapper::Robot {
 public:
  const mapper::RobotGeometry& geometry() const override { return geometry_; }
  std::optional<mapper::SensorFrame> next_frame() override {
    mapper::SensorFrame f;
    f.time_s = 0.1 * static_cast<double>(++cycles_);
    for (int k = 0; k < 100; ++k) {
      mapper::SonarReading r;
      r.index = k % 16;
      r.range_m = 1.0 + 0.01 * k;  // later readings are longer: the newest is recognisable
      r.echo = true;
      f.sonar.push_back(r);
    }
    return f;
  }
  void command(const mapper::VelocityCommand&) override {}
  void stop() override {}

 private:
  mapper::RobotGeometry geometry_ = mapper::p2at_geometry();
  int cycles_ = 0;
};

TEST(P2osServer, ManyReadingsInOneCycleFitOneSip) {
  auto [robot_end, client] = make_memory_pair();
  ChattyBody body;
  P2osServerOptions o;
  o.cycle = 20ms;
  P2osServer server(*robot_end, body, o);
  std::atomic<bool> stop{false};
  std::string escaped;
  std::thread thread([&] {
    try {
      server.run(stop);
    } catch (const std::exception& e) {
      escaped = e.what();
    }
  });
  p2os::PacketDecoder decoder;
  client->write(p2os::encode_command(Command::kSync0));
  ASSERT_TRUE(await(*client, decoder, 0));
  client->write(p2os::encode_command(Command::kSync1));
  ASSERT_TRUE(await(*client, decoder, 1));
  client->write(p2os::encode_command(Command::kSync2));
  ASSERT_TRUE(await(*client, decoder, 2));
  client->write(p2os::encode_command(Command::kOpen));
  std::vector<p2os::Sip> sips;
  for (int i = 0; i < 3; ++i) {
    const auto packet = await(*client, decoder, p2os::kSipStopped);
    if (!packet) break;
    sips.push_back(p2os::decode_sip(packet->body));
  }
  stop = true;
  thread.join();
  EXPECT_EQ(escaped, "");
  ASSERT_EQ(sips.size(), 3u);
  for (const p2os::Sip& sip : sips) {
    ASSERT_EQ(sip.sonars.size(), 16u);
    for (const p2os::SipSonar& r : sip.sonars) {
      // transducer i's newest reading is k = 96 + i for i < 4, else 80 + i
      const int k = r.number < 4 ? 96 + r.number : 80 + r.number;
      EXPECT_NEAR(r.range * 0.268 / 1000.0, 1.0 + 0.01 * k, 0.0003) << int(r.number);
    }
  }
}

// A client packet whose count byte was corrupted to 200 (a USB-serial adapter flips a bit):
// the decoder waited for 203 bytes, so every command behind it was held back until enough
// keep-alives had piled up behind it, 18 bytes per 200 ms: over 2 s, past the watchdog. Now a
// packet still incomplete 500 ms after it began is abandoned and the commands behind it obeyed.
TEST(P2osServer, CorruptedCountDoesNotHoldBackLaterCommands) {
  Served s;
  s.open();
  ASSERT_TRUE(await(*s.client, s.decoder, p2os::kSipStopped));
  const std::vector<std::uint8_t> cut = {0xFA, 0xFB, 0xC8, 0x0B, 0x3B};
  s.client->write(cut);
  for (int i = 0; i < 5; ++i) {  // 1 s of keep-alives, as P2osRobot sends them
    s.client->write(p2os::encode_command(Command::kVel, 250));
    s.client->write(p2os::encode_command(Command::kRVel, 0));
    std::this_thread::sleep_for(200ms);
  }
  EXPECT_NEAR(s.body.current().v_mps, 0.25, 1e-12);
  EXPECT_GE(s.server->stats().bad_bytes, 1u);
}

}  // namespace
}  // namespace cogmap::hw

namespace cogmap::hw {
namespace {

// Reads a CONFIGpac body field by field in the order ARIA's ArRobotConfigPacketReader does.
struct ConfigCursor {
  const std::vector<std::uint8_t>& b;
  std::size_t at = 1;  // after the type byte
  std::string str() {
    std::string s;
    while (at < b.size() && b[at] != 0) s.push_back(static_cast<char>(b[at++]));
    ++at;
    return s;
  }
  int u8() { return at < b.size() ? b[at++] : -1; }
  int u16() {
    if (at + 2 > b.size()) return -1;
    const int v = b[at] | (b[at + 1] << 8);
    at += 2;
    return v;
  }
};

// ARIA sends CONFIG (#18) at every connection and waits up to 1 s for the CONFIGpac (0x20);
// with RequireConfigPacket set it refuses a robot that does not answer. The server ignored
// it. The reply carries the model's limits where ARIA takes its absolute maxima from.
TEST(P2osServer, ConfigRequestIsAnsweredInAriasLayout) {
  P2osServerOptions o;
  o.watchdog = 1500ms;
  Served s(o);
  s.open();
  s.client->write(p2os::encode_command(Command::kConfig, 1));  // ARIA: comInt(CONFIG, 1)
  const auto packet = await(*s.client, s.decoder, p2os::kConfigReply);
  ASSERT_TRUE(packet);
  ASSERT_LE(packet->body.size() + 5, p2os::kMaxCount);
  const p2os::ConfigReply reply = p2os::decode_config(packet->body);
  EXPECT_EQ(reply.robot_type, "Pioneer");
  EXPECT_EQ(reply.subtype, "p2at");
  ConfigCursor c{packet->body};
  c.str();
  c.str();
  c.str();
  c.u8();
  EXPECT_EQ(c.u16(), 100);  // RotVelTop, deg/s (1.74 rad/s)
  EXPECT_EQ(c.u16(), 750);  // TransVelTop, mm/s
  EXPECT_GT(c.u16(), 0);    // RotAccTop
  EXPECT_GT(c.u16(), 0);    // TransAccTop
  c.u16();
  EXPECT_EQ(c.str(), "cogmap-sim");
  EXPECT_EQ(c.u8(), 100);  // SIP cycle, ms
  c.u8();
  c.u8();
  c.u16();
  EXPECT_EQ(c.u16(), 1);  // front sonar
  EXPECT_EQ(c.u8(), 1);   // rear sonar
  c.u16();
  c.u16();
  EXPECT_EQ(c.u16(), 1500);  // watchdog, ms
  c.u8();
  for (int i = 0; i < 4; ++i) c.u16();
  EXPECT_EQ(c.u16(), 100);  // RotVelMax
  EXPECT_EQ(c.u16(), 750);  // TransVelMax
  for (int i = 0; i < 5; ++i) c.u16();
  EXPECT_EQ(c.u16(), 300);  // TransAccel
  EXPECT_EQ(c.u16(), 600);  // TransDecel
  for (int i = 0; i < 3; ++i) c.u16();
  for (int i = 0; i < 4; ++i) c.u8();
  EXPECT_EQ(c.u8(), 0);  // autobaud off: ARIA must not switch the serial rate
  EXPECT_EQ(c.u8(), 0);  // no gyro
  c.u16();
  c.u8();
  c.u8();
  c.u16();
  c.u16();
  EXPECT_EQ(c.str(), "cogmap");  // firmware version
  for (int i = 0; i < 2; ++i) c.u16();
  c.u8();
  for (int i = 0; i < 6; ++i) EXPECT_GE(c.u16(), 0) << "lateral field " << i;
  EXPECT_EQ(c.at, packet->body.size());
  // The SIP stream goes on.
  EXPECT_TRUE(await(*s.client, s.decoder, p2os::kSipStopped));
}

// SETO (#7) restarts the position counters where the robot stands. ROS's p2os sends it right
// after connecting, as the type byte with an argument type and no value, and zeroes its own
// counters; the server ignored it, so its first odometry step ran from 0 to our counters.
TEST(P2osServer, SetoRestartsThePositionCounters) {
  Served s;
  s.open();
  s.client->write(p2os::encode_command(Command::kVel, 400));
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(await(*s.client, s.decoder, p2os::kSipMoving));
  s.client->write(p2os::encode_command(Command::kVel, 0));
  std::optional<p2os::Packet> packet = await(*s.client, s.decoder, p2os::kSipStopped);
  ASSERT_TRUE(packet);
  EXPECT_GT(p2os::decode_sip(packet->body).x_pos, 0);
  s.client->write(p2os::frame(std::vector<std::uint8_t>{7, p2os::kArgPositive}));  // ROS's SETO
  // Drain what was in flight, then the counters read zero.
  for (int i = 0; i < 3; ++i) packet = await(*s.client, s.decoder, p2os::kSipStopped);
  ASSERT_TRUE(packet);
  const p2os::Sip sip = p2os::decode_sip(packet->body);
  EXPECT_EQ(sip.x_pos, 0);
  EXPECT_EQ(sip.y_pos, 0);
  EXPECT_EQ(sip.th_pos, 0);
}

// The connection of Player's and ROS's p2os as they send it: SYNC0 resent before the first
// echo was read (so one extra echo of each comes back and a second SYNC1 follows), a bare
// OPEN, PULSE, SONAR 0, accelerations (one negative, 0x1B), the PID gains ROTKP..TRANSKI,
// BUMPSTALL, SONAR 1, SETO without a value; then commands ARIA or others send: JOYDRIVE,
// SOUNDTOG, ENCODER 1 and IOREQUEST 2 packet requests, HOSTBAUD, a string command (TTY2,
// 0x2B), and ARIA's "WMS2\r" radio-modem bytes before the first SYNC. None may break the sync
// or the stream; the motion commands after them must still drive. ENCODER 1 brings one encoder
// packet after the next SIP, IOREQUEST 2 an IO packet after every SIP (both used to be ignored:
// an ARIA client asking for them waited in vain; p2os_server_streams_test.cc has the rest).
TEST(P2osServer, PlayerAndAriaConnectSequencesAreServed) {
  Served s;
  const auto send = [&](std::uint8_t cmd, std::optional<int> arg = std::nullopt) {
    s.client->write(arg ? p2os::encode_command(static_cast<Command>(cmd), *arg)
                        : p2os::encode_command(static_cast<Command>(cmd)));
  };
  const std::string modem = "WMS2\r";
  s.client->write(std::vector<std::uint8_t>(modem.begin(), modem.end()));
  send(0);
  send(0);
  auto types = types_for(*s.client, s.decoder, 150ms);
  EXPECT_EQ(std::count(types.begin(), types.end(), 0), 2);  // each SYNC0 echoed
  send(1);
  send(1);  // p2os answers the second SYNC0 echo with another SYNC1
  types = types_for(*s.client, s.decoder, 150ms);
  EXPECT_EQ(std::count(types.begin(), types.end(), 1), 1);
  send(2);
  const auto id = await(*s.client, s.decoder, 2);
  ASSERT_TRUE(id);
  EXPECT_EQ(p2os::decode_sync2(id->body).subclass, "p2at");
  send(1);  // OPEN, bare
  send(0);  // PULSE
  send(28, 0);
  send(5, 300);
  send(5, -300);
  send(23, 100);  // SETRA
  for (std::uint8_t gain = 82; gain <= 87; ++gain) send(gain, 40);
  send(44, 3);  // BUMPSTALL
  send(28, 1);
  s.client->write(p2os::frame(std::vector<std::uint8_t>{7, p2os::kArgPositive}));  // SETO
  send(47, 1);                                                                     // JOYDRIVE
  send(92, 0);                                                                     // SOUNDTOG
  send(19, 1);                                                                     // ENCODER 1
  send(40, 2);                                                                     // IOREQUEST 2
  send(50, 0);                                                                     // HOSTBAUD 9600
  s.client->write(p2os::encode_command(static_cast<Command>(42), std::string_view("hello")));
  send(4, 1);  // ENABLE
  send(11, 200);
  send(21, -10);
  types = types_for(*s.client, s.decoder, 600ms);
  EXPECT_GE(std::count(types.begin(), types.end(), p2os::kSipMoving), 3);
  // The one encoder packet ENCODER 1 asked for, right behind a SIP.
  EXPECT_EQ(std::count(types.begin(), types.end(), p2os::kEncoderPacket), 1);
  EXPECT_EQ(s.server->stats().encoder_packets, 1u);
  const auto encoder = std::find(types.begin(), types.end(), p2os::kEncoderPacket);
  ASSERT_NE(encoder, types.end());
  ASSERT_NE(encoder, types.begin());
  EXPECT_TRUE(p2os::is_sip(encoder[-1]));
  // From the next SIP on (both requests long read by then), an IO packet behind every SIP.
  int sips_after = 0;
  for (auto it = encoder; it + 1 < types.end(); ++it) {
    if (!p2os::is_sip(*it)) continue;
    ++sips_after;
    EXPECT_EQ(it[1], p2os::kIoPacket) << "after SIP " << sips_after;
  }
  EXPECT_GE(sips_after, 3);
  EXPECT_NEAR(s.body.current().v_mps, 0.2, 1e-12);
  EXPECT_NEAR(s.body.current().w_radps, -10 * M_PI / 180, 1e-12);
  EXPECT_EQ(s.server->stats().syncs, 1u);
  EXPECT_EQ(s.server->stats().bad_bytes, modem.size());
}

}  // namespace
}  // namespace cogmap::hw
