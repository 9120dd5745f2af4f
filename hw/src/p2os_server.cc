// Robot side of P2OS: sync state machine, command handling, SIP, encoder and IO packet
// streaming and watchdog.
#include "cogmap/hw/p2os_server.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

namespace cogmap::hw {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

std::optional<int> command_int_argument(const p2os::Packet& packet) {
  const auto& b = packet.body;
  if (b.size() < 4) return std::nullopt;
  const int magnitude = b[2] | (b[3] << 8);
  if (b[1] == p2os::kArgPositive) return magnitude;
  if (b[1] == p2os::kArgNegative) return -magnitude;
  return std::nullopt;
}

std::optional<std::string> command_string_argument(const p2os::Packet& packet) {
  const auto& b = packet.body;
  if (b.size() < 3 || b[1] != p2os::kArgString) return std::nullopt;
  const std::size_t length = b[2];
  if (3 + length > b.size()) return std::nullopt;
  std::string text(b.begin() + 3, b.begin() + 3 + static_cast<std::ptrdiff_t>(length));
  if (const auto nul = text.find('\0'); nul != std::string::npos) text.resize(nul);
  return text;
}

std::optional<std::vector<std::pair<int, std::vector<int>>>> split_polling(
    const std::string& numbers) {
  std::vector<std::pair<int, std::vector<int>>> arrays;
  for (const char c : numbers) {
    const int number = static_cast<unsigned char>(c);
    if (number < 1 || number > 32) return std::nullopt;
    const int array = (number - 1) / 8;
    auto it =
        std::find_if(arrays.begin(), arrays.end(), [&](const auto& a) { return a.first == array; });
    if (it == arrays.end()) it = arrays.insert(arrays.end(), {array, {}});
    if (it->second.size() == 16) return std::nullopt;
    it->second.push_back(number - 1);
  }
  return arrays;
}

std::vector<std::uint8_t> config_reply_body(const p2os::RobotIdentity& identity,
                                            const mapper::RobotGeometry& geometry,
                                            std::chrono::milliseconds watchdog,
                                            std::chrono::milliseconds cycle) {
  // Field order of ARCOS's CONFIGpac as ARIA's ArRobotConfigPacketReader reads it, up to the
  // fields AMRISim also sends; ARIA reads absent later fields as 0. The speed "tops" become
  // ARIA's absolute limits, so they must be the model's real ones, never 0.
  std::vector<std::uint8_t> b = {p2os::kConfigReply};
  const auto str = [&b](const std::string& text) {
    b.insert(b.end(), text.begin(), text.end());
    b.push_back(0);
  };
  const auto u8 = [&b](long v) { b.push_back(static_cast<std::uint8_t>(std::clamp(v, 0L, 255L))); };
  const auto u16 = [&b](long v) {
    const auto w = static_cast<std::uint16_t>(std::clamp(v, 0L, 65535L));
    b.push_back(static_cast<std::uint8_t>(w & 0xFF));
    b.push_back(static_cast<std::uint8_t>(w >> 8));
  };
  const long vel = std::lround(geometry.max_speed_mps * 1000.0);
  const long rot_vel = std::lround(geometry.max_turn_rate_radps * 180.0 / std::numbers::pi);
  const long accel = std::lround(geometry.max_accel_mps2 * 1000.0);
  const long decel = std::lround(geometry.max_decel_mps2 * 1000.0);
  constexpr long kRotAccel = 100;  // deg/s^2: ARIA's own default when it gets no CONFIG
  str(identity.klass);
  str(identity.subclass);
  str("cogmap");  // serial number
  u8(0);          // "4MOTS" (P2OS on an AT)
  u16(rot_vel);   // RotVelTop, TransVelTop, RotAccTop, TransAccTop
  u16(vel);
  u16(kRotAccel);
  u16(std::max(accel, decel));
  u16(1000);  // PWMMax
  str(identity.name);
  u8(cycle.count());  // SIP cycle, ms
  u8(0);              // host baud: the rate in use
  u8(0);              // aux baud
  u16(0);             // gripper
  u16(1);             // front sonar
  u8(1);              // rear sonar (one byte, as ARCOS sends it)
  u16(0);             // low battery alarm
  u16(0);             // revcount
  u16(watchdog.count());
  u8(0);   // P2MPACS
  u16(0);  // stall PWM, stall count, joystick speeds
  u16(0);
  u16(0);
  u16(0);
  u16(rot_vel);  // current RotVelMax, TransVelMax, RotAccel, RotDecel
  u16(vel);
  u16(kRotAccel);
  u16(kRotAccel);
  for (int i = 0; i < 3; ++i) u16(0);  // rotation PID
  u16(accel);                          // TransAccel, TransDecel
  u16(decel);
  for (int i = 0; i < 3; ++i) u16(0);  // translation PID
  u8(0);                               // front, rear bumper segments, charger
  u8(0);
  u8(0);
  u8(40);  // sonar cycle, ms
  u8(0);   // autobaud off: ARIA must not send HOSTBAUD and switch its own rate
  u8(0);   // no gyro
  u16(0);  // drift factor
  u8(0);   // aux2, aux3 baud
  u8(0);
  u16(0);  // ticks per mm
  u16(0);  // shutdown voltage
  str("cogmap");
  u16(0);  // gyro CW, CCW
  u16(0);
  u8(0);   // kinematics delay
  u16(0);  // lateral tops and settings, charge threshold (no lateral axis)
  u16(0);
  u16(0);
  u16(0);
  u16(0);
  u16(0);
  return b;
}

P2osServer::P2osServer(ByteStream& stream, mapper::Robot& body, P2osServerOptions options)
    : stream_(stream), body_(body), options_(std::move(options)) {
  factors_ =
      p2os::conversion_for_subclass(options_.identity.subclass).value_or(p2os::ConversionFactors{});
}

void P2osServer::set_motion(double v_mps, double w_radps) {
  v_mps_ = v_mps;
  w_radps_ = w_radps;
  body_.command({v_mps_, w_radps_});
}

void P2osServer::handle(const p2os::Packet& packet) {
  using p2os::Command;
  const std::uint8_t cmd = packet.type();
  if (!open_) {
    // Sync state machine: each SYNC is echoed in order; anything else restarts it.
    if (sync_step_ < 3 && cmd == sync_step_ && packet.body.size() == 1) {
      if (cmd == 2) {
        const auto body = p2os::encode_sync2(options_.identity);
        stream_.write(p2os::frame(body));
      } else {
        stream_.write(p2os::encode_command(static_cast<Command>(cmd)));
      }
      ++sync_step_;
      if (sync_step_ == 3) {
        std::lock_guard lock(stats_mutex_);
        ++stats_.syncs;
      }
      return;
    }
    if (sync_step_ == 3 && cmd == static_cast<std::uint8_t>(Command::kOpen)) {
      open_ = true;
      motors_ = false;
      sonar_on_ = true;
      encoder_stream_ = io_stream_ = Stream::kOff;  // a new client asks for its own
      last_command_ = Clock::now();
      if (options_.log) options_.log("client connected: robot open");
      return;
    }
    sync_step_ = cmd == 0 && packet.body.size() == 1 ? 0 : sync_step_;
    if (cmd == 0 && packet.body.size() == 1) {
      // A fresh SYNC0 restarts the handshake (the client gave up on a previous round).
      stream_.write(p2os::encode_command(Command::kSync0));
      sync_step_ = 1;
    }
    return;
  }
  {
    std::lock_guard lock(stats_mutex_);
    ++stats_.commands;
  }
  last_command_ = Clock::now();
  const std::optional<int> arg = command_int_argument(packet);
  switch (static_cast<Command>(cmd)) {
    case Command::kClose:
      open_ = false;
      sync_step_ = 0;
      encoder_stream_ = io_stream_ = Stream::kOff;
      set_motion(0.0, 0.0);
      if (options_.log) options_.log("client closed");
      break;
    case Command::kEnable:
      motors_ = arg.value_or(0) != 0;
      if (!motors_) set_motion(0.0, 0.0);
      break;
    case Command::kSonar:
      sonar_on_ = arg.value_or(0) != 0;
      break;
    case Command::kSonarCycle:
      if (!arg || *arg < 2 || *arg > 120) {
        if (options_.log) options_.log("SONAR_CYCLE outside 2-120 ms ignored");
      } else if (options_.set_sonar_cycle_ms) {
        try {
          options_.set_sonar_cycle_ms(*arg);
        } catch (const std::invalid_argument& e) {
          if (options_.log) options_.log(std::string("SONAR_CYCLE ignored: ") + e.what());
        }
      }
      break;
    case Command::kPolling: {
      const std::optional<std::string> text = command_string_argument(packet);
      if (!text) break;
      // ARCOS: an empty string disables the sonar but keeps the sequences.
      if (text->empty()) {
        sonar_on_ = false;
        break;
      }
      const auto arrays = split_polling(*text);
      if (!arrays) {
        if (options_.log) options_.log("POLLING with a number outside 1-32 ignored");
        break;
      }
      for (const auto& [array, sequence] : *arrays) {
        if (!options_.set_sonar_polling) break;
        try {
          options_.set_sonar_polling(array, sequence);
        } catch (const std::invalid_argument& e) {
          if (options_.log) options_.log(std::string("POLLING ignored: ") + e.what());
        }
      }
      break;
    }
    case Command::kVel:
      if (motors_ && arg) set_motion(*arg * factors_.velocity_mmps_per_unit / 1000.0, w_radps_);
      break;
    case Command::kRVel:
      if (motors_ && arg) set_motion(v_mps_, *arg * std::numbers::pi / 180.0);
      break;
    case Command::kVel2:
      if (motors_ && arg) {
        // Left wheel in the high byte, right in the low, each signed x 20 mm/s.
        const auto bits = static_cast<std::uint16_t>(*arg);
        const double left_mps = static_cast<std::int8_t>(bits >> 8) * 0.020;
        const double right_mps = static_cast<std::int8_t>(bits & 0xFF) * 0.020;
        // The wheels' difference over the track the firmware converts with (the model's
        // odometry track, 2 / DiffConvFactor), as a skid-steer's wheel speeds relate to its
        // turn: the same track the SIP's wheel speeds and the encoder counts use.
        set_motion((left_mps + right_mps) / 2.0,
                   (right_mps - left_mps) / body_.geometry().odometry_track_m);
      }
      break;
    case Command::kSetO:
      // The position counters restart at zero where the robot stands. ROS's p2os sends it
      // (with an argument type byte and no value) right after connecting and zeroes its own
      // counters: ignored, its first odometry step ran from 0 to wherever ours stood.
      if (have_odometry_) origin_ = last_odometry_;
      options_.initial_x_count = 0;
      options_.initial_y_count = 0;
      break;
    case Command::kConfig:
      // ARIA asks at every connection and waits up to 1 s for the reply (a client that sets
      // RequireConfigPacket fails without it); AMRISim and ARCOS answer.
      stream_.write(p2os::frame(config_reply_body(options_.identity, body_.geometry(),
                                                  options_.watchdog, options_.cycle)));
      break;
    case Command::kStop:
    case Command::kEStop:
      set_motion(0.0, 0.0);
      break;
    case Command::kEncoder:
      // ARIA's requestEncoderPackets sends 2 and stopEncoderPackets 0; its connection tester
      // asks for one packet at a time with 1. AMRISim (MobileSim) ignores ENCODER and IOREQUEST.
      encoder_stream_ = stream_request(arg);
      break;
    case Command::kIoRequest:
      // ARIA's requestIOPackets sends 2, stopIOPackets 0, its IO request test 1.
      io_stream_ = stream_request(arg);
      break;
    default:
      break;  // PULSE and commands this model does not implement: watchdog only
  }
}

P2osServer::Stream P2osServer::stream_request(std::optional<int> arg) {
  if (!arg || *arg <= 0) return Stream::kOff;
  return *arg == 1 ? Stream::kOnce : Stream::kEverySip;
}

void P2osServer::count_wheel_travel(const mapper::Pose2& from, const mapper::Pose2& to) {
  // The wheel travel the firmware's odometry integrates back into this step: the chord along
  // the heading (signed by direction) and the turn over the model's odometry track (2 /
  // DiffConvFactor of its ARIA parameters), so the counts agree with the SIP's pose.
  const mapper::Pose2 step = from.inverse().compose(to);
  const double chord_mm = std::hypot(step.x_m, step.y_m) * 1000.0;
  const double forward_mm = step.x_m < 0.0 ? -chord_mm : chord_mm;
  const double turn_rad = mapper::wrap_angle_rad(to.theta_rad - from.theta_rad);
  const double half_track_mm = body_.geometry().odometry_track_m * 1000.0 / 2.0;
  left_wheel_mm_ += forward_mm - turn_rad * half_track_mm;
  right_wheel_mm_ += forward_mm + turn_rad * half_track_mm;
}

void P2osServer::send_requested_packets() {
  if (encoder_stream_ != Stream::kOff) {
    // One count per position unit (DistConvFactor mm, 1.32 for the p2at), the unit of XPOS
    // and YPOS: P2OS reports no encoder ticks per mm (CONFIG sends 0, as AMRISim's does), so
    // this is the one scale a client already has. The 32-bit counters wrap.
    const auto count = [this](double mm) {
      const auto ticks = std::llround(mm / factors_.distance_mm_per_unit);
      return static_cast<std::int32_t>(static_cast<std::uint32_t>(ticks));
    };
    stream_.write(
        p2os::frame(p2os::encode_encoder_packet({count(left_wheel_mm_), count(right_wheel_mm_)})));
    if (encoder_stream_ == Stream::kOnce) encoder_stream_ = Stream::kOff;
    std::lock_guard lock(stats_mutex_);
    ++stats_.encoder_packets;
  }
  if (io_stream_ != Stream::kOff) {
    // The simulator has no user I/O. The lists mirror what the SIP carries of it (one DIGIN
    // byte, one DIGOUT byte, one ANALOG reading), all zero there as here.
    stream_.write(p2os::frame(p2os::encode_io_packet({{0}, {0}, {0}})));
    if (io_stream_ == Stream::kOnce) io_stream_ = Stream::kOff;
    std::lock_guard lock(stats_mutex_);
    ++stats_.io_packets;
  }
}

void P2osServer::step_and_send_sip() {
  const std::optional<mapper::SensorFrame> frame = body_.next_frame();
  if (!frame) return;
  if (!have_odometry_) {
    origin_ = frame->odometry;  // counters start at zero where the robot powers up
    have_odometry_ = true;
  } else {
    count_wheel_travel(last_odometry_, frame->odometry);
  }
  last_odometry_ = frame->odometry;
  if (!open_) return;
  const mapper::Pose2 rel = origin_.inverse().compose(frame->odometry);
  p2os::Sip sip;
  sip.moving = v_mps_ != 0.0 || w_radps_ != 0.0;
  const auto wrap15 = [](double units) {
    return static_cast<std::uint16_t>(static_cast<std::int64_t>(std::llround(units)) & 0x7FFF);
  };
  sip.x_pos = wrap15(options_.initial_x_count + rel.x_m * 1000.0 / factors_.distance_mm_per_unit);
  sip.y_pos = wrap15(options_.initial_y_count + rel.y_m * 1000.0 / factors_.distance_mm_per_unit);
  sip.th_pos =
      static_cast<std::int16_t>(std::llround(rel.theta_rad / factors_.angle_rad_per_unit) & 0xFFF);
  const double half_track_m = body_.geometry().odometry_track_m / 2.0;
  sip.l_vel = static_cast<std::int16_t>(std::lround((v_mps_ - w_radps_ * half_track_m) * 1000.0));
  sip.r_vel = static_cast<std::int16_t>(std::lround((v_mps_ + w_radps_ * half_track_m) * 1000.0));
  sip.battery = 130;
  sip.stall_left = frame->stall_left ? 1 : 0;
  sip.stall_right = frame->stall_right ? 1 : 0;
  sip.flags = static_cast<std::uint16_t>((motors_ ? 1 : 0) | (sonar_on_ ? 0x1E : 0));
  sip.battery_x10 = 130;
  sip.charge_state = 0;
  sip.rot_vel = static_cast<std::int16_t>(std::lround(w_radps_ * 1800.0 / std::numbers::pi));
  if (sonar_on_) {
    const double max_m = body_.geometry().sonar_max_range_m;
    // No echo: a raw range that converts back to at least the maximum.
    const auto no_echo_raw = static_cast<std::uint16_t>(
        std::min(65535.0, std::ceil(max_m * 1000.0 / factors_.sonar_mm_per_unit) + 1));
    // As on P2OS, a SIP carries each transducer's newest reading: a transducer that fired twice
    // in the cycle (SONAR_CYCLE below 50 ms, a short POLLING sequence) is reported once. 100
    // readings used to make a 330-byte packet, and frame() threw out of run().
    for (const mapper::SonarReading& r : frame->sonar) {
      if (r.index < 0 || r.index > 255) continue;
      const double raw = r.range_m * 1000.0 / factors_.sonar_mm_per_unit;
      const p2os::SipSonar reading{
          static_cast<std::uint8_t>(r.index),
          r.echo ? static_cast<std::uint16_t>(std::clamp(std::round(raw), 0.0, 65535.0))
                 : no_echo_raw};
      const auto same = std::find_if(sip.sonars.begin(), sip.sonars.end(),
                                     [&](const p2os::SipSonar& s) { return s.number == r.index; });
      if (same != sip.sonars.end()) sip.sonars.erase(same);
      sip.sonars.push_back(reading);
    }
    // A body with more transducers than one packet holds (3 bytes a reading) keeps the newest.
    p2os::Sip bare = sip;
    bare.sonars.clear();
    const std::size_t fixed = p2os::encode_sip(bare).size();
    const std::size_t room = (p2os::kMaxCount - 2 - fixed) / 3;
    if (sip.sonars.size() > room) {
      sip.sonars.erase(sip.sonars.begin(), sip.sonars.end() - static_cast<std::ptrdiff_t>(room));
    }
  }
  stream_.write(p2os::frame(p2os::encode_sip(sip)));
  {
    std::lock_guard lock(stats_mutex_);
    ++stats_.sips_sent;
  }
  send_requested_packets();
}

void P2osServer::run(const std::atomic<bool>& stop) {
  std::uint8_t buf[512];
  auto next_cycle = Clock::now() + options_.cycle;
  p2os::StalledPacketGuard stall_guard(options_.partial_packet_timeout);
  try {
    while (!stop) {
      const auto now = Clock::now();
      if (now >= next_cycle) {
        next_cycle += options_.cycle;
        if (next_cycle < now) next_cycle = now + options_.cycle;  // fell behind: do not burst
        if (reset_requested_.exchange(false)) {
          stream_.write(p2os::frame(std::vector<std::uint8_t>{p2os::kResetPacket}));
          open_ = false;
          sync_step_ = 0;
          set_motion(0.0, 0.0);
          origin_ = last_odometry_;  // the controller's counters restart at zero
          options_.initial_x_count = 0;
          options_.initial_y_count = 0;
          left_wheel_mm_ = right_wheel_mm_ = 0.0;
          encoder_stream_ = io_stream_ = Stream::kOff;
        }
        if (open_ && Clock::now() - last_command_ > options_.watchdog &&
            (v_mps_ != 0.0 || w_radps_ != 0.0)) {
          set_motion(0.0, 0.0);
          {
            std::lock_guard lock(stats_mutex_);
            ++stats_.watchdog_stops;
          }
          if (options_.log) options_.log("watchdog: no command for 2 s, stopping");
        }
        // A client that sends nothing may still be reading: Player's and ROS's p2os send no
        // command while idle (their `pulse` is off by default) and block until the next SIP,
        // and a real controller streams until CLOSE. So a silent client is dropped only once
        // the link stops taking bytes (a pty whose client died fills in about 20 s).
        if (open_ && Clock::now() - last_command_ > options_.client_timeout &&
            !stream_.accepts_writes()) {
          open_ = false;
          sync_step_ = 0;
          encoder_stream_ = io_stream_ = Stream::kOff;
          {
            std::lock_guard lock(stats_mutex_);
            ++stats_.client_timeouts;
          }
          if (options_.log) options_.log("client silent: closing, waiting for a new handshake");
        }
        step_and_send_sip();
        continue;
      }
      const auto wait = std::chrono::duration_cast<milliseconds>(next_cycle - now);
      const std::size_t n = stream_.read(buf, std::max(wait, milliseconds(1)));
      if (n > 0) decoder_.feed({buf, n});
      // A client packet cut off (a corrupted count byte, a client killed mid-write) must not
      // hold back the commands behind it until 200 bytes have piled up: at the keep-alive's
      // 18 bytes per 200 ms that took over 2 s, and the watchdog had stopped the robot.
      do {
        while (auto packet = decoder_.next()) handle(*packet);
      } while (stall_guard.check(decoder_, Clock::now()));
      {
        std::lock_guard lock(stats_mutex_);
        stats_.bad_bytes = decoder_.dropped_bytes();
      }
    }
  } catch (const StreamClosed&) {
    // The client hung up: the robot stops, as a real one does when its watchdog fires.
    set_motion(0.0, 0.0);
  }
}

}  // namespace cogmap::hw
