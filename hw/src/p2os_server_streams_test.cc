// The encoder (ENCODER #19, ENCODERpac 0x90) and IO (IOREQUEST #40, IOpac 0xF0) packets: their
// layout as ARIA's ArRobot::processEncoderPacket / processIOPacket read it, and the server
// sending them after its SIPs. The server ignored both requests, so an ARIA client that asked
// for encoder or IO packets (requestEncoderPackets, requestIOPackets) never got any.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "p2os_served.h"

namespace cogmap::hw {
namespace {

using namespace std::chrono_literals;
using p2os::Command;
using testing::Served;
using testing::types_for;

TEST(P2osEncoderPacket, LayoutIsTwoSignedLittleEndianCounts) {
  const std::vector<std::uint8_t> body = {0x90, 0x10, 0x00, 0x00, 0x00, 0xFE, 0xFF, 0xFF, 0xFF};
  EXPECT_EQ(p2os::encode_encoder_packet({16, -2}), body);
  const p2os::EncoderCounts c = p2os::decode_encoder_packet(body);
  EXPECT_EQ(c.left, 16);
  EXPECT_EQ(c.right, -2);
  try {
    p2os::decode_encoder_packet(std::vector<std::uint8_t>(body.begin(), body.end() - 1));
    FAIL() << "expected DecodeError";
  } catch (const p2os::DecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("encoder packet too short: field RIGHT ENCODER"),
              std::string::npos)
        << e.what();
  }
}

TEST(P2osIoPacket, LayoutIsCountedDigitalInOutAndAnalog) {
  const p2os::IoReport io{{0x81}, {0x02, 0x03}, {0x3FF, 7}};
  const std::vector<std::uint8_t> body = {0xF0, 1, 0x81, 2, 0x02, 0x03, 2, 0xFF, 0x03, 7, 0};
  EXPECT_EQ(p2os::encode_io_packet(io), body);
  const p2os::IoReport back = p2os::decode_io_packet(body);
  EXPECT_EQ(back.digital_in, io.digital_in);
  EXPECT_EQ(back.digital_out, io.digital_out);
  EXPECT_EQ(back.analog, io.analog);
  try {
    p2os::decode_io_packet(std::vector<std::uint8_t>(body.begin(), body.end() - 1));
    FAIL() << "expected DecodeError";
  } catch (const p2os::DecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("IO packet too short: field ANALOG"), std::string::npos)
        << e.what();
  }
}

// An encoder packet and the SIP it followed.
struct EncoderStep {
  p2os::Sip sip;
  p2os::EncoderCounts counts;
};

// The next `n` encoder packets, each with the SIP right before it (a packet that does not
// follow a SIP directly fails the test).
std::vector<EncoderStep> encoder_steps(Served& s, std::size_t n) {
  std::vector<EncoderStep> steps;
  std::optional<p2os::Sip> sip_before;  // the previous packet, when it was a SIP
  const auto end = std::chrono::steady_clock::now() + 3s;
  std::uint8_t buf[512];
  while (steps.size() < n && std::chrono::steady_clock::now() < end) {
    while (auto p = s.decoder.next()) {
      if (p->type() == p2os::kEncoderPacket && steps.size() < n) {
        EXPECT_TRUE(sip_before) << "encoder packet at stream offset " << p->offset
                                << " does not follow a SIP";
        if (sip_before) steps.push_back({*sip_before, p2os::decode_encoder_packet(p->body)});
      }
      sip_before.reset();
      if (p2os::is_sip(p->type())) sip_before = p2os::decode_sip(p->body);
    }
    s.decoder.feed({buf, s.client->read(buf, 10ms)});
  }
  return steps;
}

P2osServerOptions fast_cycle() {
  P2osServerOptions o;
  o.cycle = 20ms;  // each SIP is still 100 ms of the body's time
  return o;
}

// ENCODER 2 streams the wheels' travel after every SIP, in the SIP's position units (1.32 mm
// for the p2at): driving straight both wheels count what XPOS counts; turning in place they
// part by the heading change times the odometry track (2 / DiffConvFactor = 588 mm).
TEST(P2osServerStreams, EncoderCountsFollowTheWheels) {
  Served s(fast_cycle());
  s.open();
  s.client->write(p2os::encode_command(Command::kEncoder, 2));
  s.client->write(p2os::encode_command(Command::kVel, 300));
  const std::vector<EncoderStep> straight = encoder_steps(s, 8);
  ASSERT_EQ(straight.size(), 8u);
  for (const EncoderStep& step : straight) {
    EXPECT_NEAR(step.counts.left, step.counts.right, 1);
    EXPECT_NEAR(step.counts.left, step.sip.x_pos, 1);
  }
  for (std::size_t i = 1; i < straight.size(); ++i) {
    EXPECT_GE(straight[i].counts.left, straight[i - 1].counts.left);
  }
  EXPECT_GT(straight.back().counts.left, straight.front().counts.left + 100);  // 22.7 a SIP

  s.client->write(p2os::encode_command(Command::kVel, 0));
  s.client->write(p2os::encode_command(Command::kRVel, 30));
  encoder_steps(s, 3);  // the turn begins
  const std::vector<EncoderStep> turn = encoder_steps(s, 6);
  ASSERT_EQ(turn.size(), 6u);
  const EncoderStep& a = turn.front();
  const EncoderStep& b = turn.back();
  int heading_units = (b.sip.th_pos - a.sip.th_pos) & 0xFFF;  // 12-bit heading counter
  if (heading_units > 2048) heading_units -= 4096;
  const double heading_rad = heading_units * 2.0 * std::numbers::pi / 4096.0;
  const int parted = (b.counts.right - b.counts.left) - (a.counts.right - a.counts.left);
  EXPECT_GT(heading_rad, 0.2);  // 30 deg/s for 0.5 s of the body's time
  EXPECT_NEAR(parted * 1.32 / 588.2353, heading_rad, 0.01);
  EXPECT_NEAR(b.counts.left + b.counts.right, a.counts.left + a.counts.right, 2);
  EXPECT_LT(b.counts.left, a.counts.left);  // the left wheels run backwards
}

// ENCODER 0 stops the stream, ENCODER 1 brings exactly one packet, and a new client does not
// inherit the stream of the one before.
TEST(P2osServerStreams, EncoderZeroStopsOneSendsOnce) {
  Served s(fast_cycle());
  s.open();
  s.client->write(p2os::encode_command(Command::kEncoder, 2));
  ASSERT_EQ(encoder_steps(s, 3).size(), 3u);
  s.client->write(p2os::encode_command(Command::kEncoder, 0));
  types_for(*s.client, s.decoder, 100ms);  // what was in flight
  auto types = types_for(*s.client, s.decoder, 300ms);
  EXPECT_EQ(std::count(types.begin(), types.end(), p2os::kEncoderPacket), 0);
  EXPECT_GE(std::count_if(types.begin(), types.end(), p2os::is_sip), 5);
  s.client->write(p2os::encode_command(Command::kEncoder, 1));
  types = types_for(*s.client, s.decoder, 400ms);
  EXPECT_EQ(std::count(types.begin(), types.end(), p2os::kEncoderPacket), 1);

  s.client->write(p2os::encode_command(Command::kEncoder, 2));
  s.client->write(p2os::encode_command(Command::kClose));
  types_for(*s.client, s.decoder, 100ms);
  s.open();
  types = types_for(*s.client, s.decoder, 300ms);
  EXPECT_GE(std::count_if(types.begin(), types.end(), p2os::is_sip), 5);
  EXPECT_EQ(std::count(types.begin(), types.end(), p2os::kEncoderPacket), 0);
}

// A controller reset restarts the encoder counters at zero, as it does the position counters.
TEST(P2osServerStreams, ResetRestartsTheEncoderCounts) {
  Served s(fast_cycle());
  s.open();
  s.client->write(p2os::encode_command(Command::kEncoder, 2));
  s.client->write(p2os::encode_command(Command::kVel, 400));
  const std::vector<EncoderStep> before = encoder_steps(s, 5);
  ASSERT_EQ(before.size(), 5u);
  EXPECT_GT(before.back().counts.left, 50);
  s.server->request_reset();
  ASSERT_TRUE(testing::await(*s.client, s.decoder, p2os::kResetPacket));
  s.open();
  s.client->write(p2os::encode_command(Command::kEncoder, 1));
  const std::vector<EncoderStep> after = encoder_steps(s, 1);
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(after[0].counts.left, 0);  // the reset stopped the robot too
  EXPECT_EQ(after[0].counts.right, 0);
}

// IOREQUEST 1 brings one IO packet, 2 one after every SIP, 0 none: in ARIA's layout, with the
// simulator's user I/O all zero (one DIGIN byte, one DIGOUT byte, one analog reading, as in
// the SIP).
TEST(P2osServerStreams, IoRequestSendsZeroedIoPackets) {
  Served s(fast_cycle());
  s.open();
  types_for(*s.client, s.decoder, 100ms);
  s.client->write(p2os::encode_command(Command::kIoRequest, 1));
  const auto io = testing::await(*s.client, s.decoder, p2os::kIoPacket);
  ASSERT_TRUE(io);
  EXPECT_EQ(io->body, (std::vector<std::uint8_t>{0xF0, 1, 0, 1, 0, 1, 0, 0}));
  auto types = types_for(*s.client, s.decoder, 300ms);
  EXPECT_EQ(std::count(types.begin(), types.end(), p2os::kIoPacket), 0);

  s.client->write(p2os::encode_command(Command::kIoRequest, 2));
  types_for(*s.client, s.decoder, 100ms);
  types = types_for(*s.client, s.decoder, 300ms);
  int sips = 0;
  for (auto it = types.begin(); it + 1 < types.end(); ++it) {
    if (!p2os::is_sip(*it)) continue;
    ++sips;
    EXPECT_EQ(it[1], p2os::kIoPacket) << "after SIP " << sips;
  }
  EXPECT_GE(sips, 5);

  s.client->write(p2os::encode_command(Command::kIoRequest, 0));
  types_for(*s.client, s.decoder, 100ms);
  types = types_for(*s.client, s.decoder, 300ms);
  EXPECT_EQ(std::count(types.begin(), types.end(), p2os::kIoPacket), 0);
  EXPECT_GE(std::count_if(types.begin(), types.end(), p2os::is_sip), 5);
}

}  // namespace
}  // namespace cogmap::hw
