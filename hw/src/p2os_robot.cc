// P2osRobot: SIP -> SensorFrame, keep-alive, reconnection, clean shutdown (the handshake is
// p2os_handshake.cc).
#include "cogmap/hw/p2os_robot.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cogmap/hw/robot_log.h"
#include "cogmap/mapper/seam/robot_models.h"
#include "log_checks.h"
#include "p2os_text.h"

namespace cogmap::hw {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {

constexpr milliseconds kReadSlice{20};       // I/O loop granularity: command latency bound
constexpr std::uint64_t kLoggedBadSips = 5;  // then every 1000th: a bad peer must not flood

}  // namespace

P2osRobot::P2osRobot(std::unique_ptr<ByteStream> stream, P2osRobotOptions options)
    : stream_(std::move(stream)),
      options_(std::move(options)),
      geometry_(mapper::p2at_geometry()),
      stall_guard_(options_.partial_packet_timeout) {
  start_ = Clock::now();
  if (!handshake()) {
    throw P2osHandshakeError(stream_->name() + ": P2OS handshake failed: " + failure_,
                             failure_kind_);
  }
  thread_ = std::thread([this] { io_loop(); });
}

P2osRobot::~P2osRobot() { shutdown(); }

void P2osRobot::log(const std::string& message) const {
  if (options_.log) options_.log(message);
}

void P2osRobot::send(const std::vector<std::uint8_t>& packet) {
  stream_->write(packet);
  last_sent_ = Clock::now();
}

void P2osRobot::receive(milliseconds timeout) {
  // While a packet is incomplete, wait no longer than its remaining allowance: a packet cut
  // off in the middle must not hide the packets behind it.
  std::uint8_t buf[512];
  const std::size_t n = stream_->read(buf, stall_guard_.cap(decoder_, Clock::now(), timeout));
  note_drops();  // what the last next() calls discarded, also while a handshake runs
  if (n > 0) decoder_.feed({buf, n});
}

void P2osRobot::note_drops() {
  std::lock_guard lock(mutex_);
  if (stats_.dropped_bytes == decoder_.dropped_bytes()) return;
  stats_.dropped_bytes = decoder_.dropped_bytes();
  if (!decoder_.drops().empty()) last_drop_ = decoder_.drops().back();
}

std::optional<p2os::Packet> P2osRobot::read_packet(milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    if (auto p = decoder_.next()) return p;
    if (stall_guard_.check(decoder_, Clock::now())) continue;
    // Rounded up, so the wait lasts the whole timeout: truncated, it ended up to 1 ms early
    // and the handshake started one more attempt in the last moment before its bound.
    const auto left = std::chrono::ceil<milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return std::nullopt;
    receive(left);
  }
}

void P2osRobot::reject_sip(const p2os::Packet& packet, const std::string& why) {
  ++bad_since_sip_;
  last_bad_sip_ = Clock::now();
  std::lock_guard lock(mutex_);
  last_bad_sip_reason_ = "SIP at stream offset " + std::to_string(packet.offset) + ": " + why;
  ++stats_.bad_sips;
  if (stats_.bad_sips <= kLoggedBadSips || stats_.bad_sips % 1000 == 0) {
    log(stream_->name() + ": " + last_bad_sip_reason_ +
        (stats_.bad_sips == kLoggedBadSips ? " (further undecodable SIPs are counted; every "
                                             "1000th is logged)"
         : stats_.bad_sips > kLoggedBadSips
             ? " (" + std::to_string(stats_.bad_sips) + " undecodable SIPs so far)"
             : ""));
  }
}

void P2osRobot::handle_sip(const p2os::Packet& packet) {
  p2os::Sip sip;
  try {
    sip = p2os::decode_sip(packet.body);
  } catch (const p2os::DecodeError& e) {
    reject_sip(packet, e.what());
    return;
  }
  const auto now = Clock::now();
  const double time_s = options_.clock == FrameClock::kHost
                            ? std::chrono::duration<double>(now - start_).count()
                            : static_cast<double>(sip_count_ + 1) * options_.sip_period_s;
  // Odometry that moves further than the robot can drive since the last frame (the bound a
  // log's frames are held to, LogLimits) is not a robot's: the fuzzer's peer sent SIPs with
  // valid checksums 48 m apart, and `drive` mapped them and exited 0 while `replay` of its own
  // recording refused them. Such a SIP is undecodable; the unwrapper forgets it.
  const OdometryUnwrapper unwrapped_before = odometry_;
  const mapper::Pose2 pose = odometry_.update(sip.x_pos, sip.y_pos, sip.th_pos);
  if (have_accepted_) {
    const std::string jump = detail::odometry_jump_problem(
        (pose.translation() - accepted_xy_).norm(), std::max(0.0, time_s - accepted_time_s_),
        geometry_.max_speed_mps, LogLimits{});
    if (!jump.empty()) {
      odometry_ = unwrapped_before;
      reject_sip(packet, jump);
      return;
    }
  }
  have_accepted_ = true;
  accepted_time_s_ = time_s;
  accepted_xy_ = pose.translation();
  last_sip_ = now;
  bad_since_sip_ = 0;
  ++sip_count_;
  mapper::SensorFrame frame;
  frame.time_s = time_s;
  frame.odometry = pose;
  frame.stall_left = sip.left_stalled();
  frame.stall_right = sip.right_stalled();
  std::uint64_t unknown = 0;
  for (const p2os::SipSonar& s : sip.sonars) {
    if (s.number >= geometry_.sonars.size()) {
      if (!reported_unknown_sonar_) {
        reported_unknown_sonar_ = true;
        log(stream_->name() + ": SIP at stream offset " + std::to_string(packet.offset) +
            ": sonar number " + std::to_string(s.number) + " is beyond the " +
            std::to_string(geometry_.sonars.size()) + " transducers of a " +
            p2os_text::printable(identity_.subclass) +
            "; readings of transducers the model does not have are dropped (counted, not "
            "logged again)");
      }
      ++unknown;
      continue;
    }
    mapper::SonarReading r;
    r.index = s.number;
    r.range_m = s.range * factors_.sonar_mm_per_unit / 1000.0;
    r.echo = r.range_m < geometry_.sonar_max_range_m;
    if (!r.echo) r.range_m = geometry_.sonar_max_range_m;
    r.time_s = frame.time_s;
    frame.sonar.push_back(r);
  }
  std::lock_guard lock(mutex_);
  ++stats_.sips;
  stats_.unknown_sonars += unknown;
  frames_.push_back(std::move(frame));
  if (frames_.size() > options_.max_queued_frames) {
    frames_.pop_front();
    ++stats_.dropped_frames;
  }
  cv_.notify_all();
}

void P2osRobot::send_motion() {
  mapper::VelocityCommand m;
  {
    std::lock_guard lock(mutex_);
    m = motion_;
    motion_dirty_ = false;
  }
  if (m.v_mps == 0.0 && m.w_radps == 0.0) {
    // Stopped: STOP is explicit; PULSE alone would keep a stale velocity.
    send(p2os::encode_command(p2os::Command::kVel, 0));
    send(p2os::encode_command(p2os::Command::kRVel, 0));
    return;
  }
  const int vel_mmps = static_cast<int>(std::lround(m.v_mps * 1000.0));
  const int rvel_degps = static_cast<int>(std::lround(m.w_radps * 180.0 / std::numbers::pi));
  send(p2os::encode_command(p2os::Command::kVel, vel_mmps));
  send(p2os::encode_command(p2os::Command::kRVel, rvel_degps));
}

void P2osRobot::io_loop() {
  Clock::time_point reconnect_since{};
  bool reconnecting = false;
  bool after_reset = false;
  try {
    for (;;) {
      {
        std::lock_guard lock(mutex_);
        if (stopping_) break;
      }
      if (reconnecting) {
        // Each handshake ends by the give-up time too: one started just before it would
        // otherwise run its whole handshake_timeout past it.
        if (handshake(reconnect_since + options_.reconnect_give_up)) {
          reconnecting = false;
          if (after_reset) {
            odometry_.rebase();  // a reset controller restarts its counters at zero
          } else {
            const double gap_s = std::chrono::duration<double>(Clock::now() - reconnect_since +
                                                               options_.silence_timeout)
                                     .count();
            odometry_.rebase_if_implausible(geometry_.max_speed_mps * (gap_s + 5.0));
          }
          after_reset = false;
          {
            std::lock_guard lock(mutex_);
            failure_.clear();
            failure_kind_ = P2osFailureKind::kNone;
          }
        } else if (Clock::now() - reconnect_since >= options_.reconnect_give_up) {
          std::lock_guard lock(mutex_);  // failure_kind_ as the handshakes judged it
          failure_ = "reconnection gave up: " + failure_;
          break;
        }
        continue;
      }
      receive(kReadSlice);
      do {
        while (auto packet = decoder_.next()) {
          if (p2os::is_sip(packet->type())) {
            handle_sip(*packet);
          } else if (packet->type() == p2os::kResetPacket) {
            log(stream_->name() + ": controller reset at stream offset " +
                std::to_string(packet->offset) + ": reconnecting");
            std::lock_guard lock(mutex_);
            ++stats_.resets;
            reconnecting = true;
            after_reset = true;
          }
        }
      } while (stall_guard_.check(decoder_, Clock::now()));
      note_drops();
      if (!reconnecting && Clock::now() - last_sip_ > options_.silence_timeout) {
        if (bad_since_sip_ >= 3 && Clock::now() - last_bad_sip_ < options_.silence_timeout / 2) {
          // Not silent: SIPs keep coming but none parses. A reconnection would only bring more
          // of them (and once reconnected, failure() was empty and the run ended "fine").
          std::lock_guard lock(mutex_);
          failure_kind_ = P2osFailureKind::kBadBytes;
          failure_ = "no SIP could be decoded for " +
                     std::to_string(options_.silence_timeout.count()) +
                     " ms: " + std::to_string(bad_since_sip_) +
                     " SIPs with valid checksums did not parse (not the standard SIP layout?); "
                     "the last: " +
                     last_bad_sip_reason_;
          break;
        }
        log(stream_->name() + ": no SIP for " + std::to_string(options_.silence_timeout.count()) +
            " ms: reconnecting");
        reconnecting = true;
      }
      if (reconnecting) {
        reconnect_since = Clock::now();
        garbage_attempts_ = answered_attempts_ = 0;  // judge what this reconnection gets
        garbage_problem_.clear();
        continue;
      }
      bool dirty;
      {
        std::lock_guard lock(mutex_);
        dirty = motion_dirty_;
      }
      if (dirty || Clock::now() - last_sent_ >= options_.keepalive_period) send_motion();
    }
    // Clean shutdown, best effort: the robot may already be gone.
    if (!reconnecting) {
      send(p2os::encode_command(p2os::Command::kSonar, 0));
      send(p2os::encode_command(p2os::Command::kStop));
      send(p2os::encode_command(p2os::Command::kClose));
    }
  } catch (const StreamError& e) {
    std::lock_guard lock(mutex_);
    failure_ = e.what();  // closed by the peer, or an I/O error: the link, not its bytes
    failure_kind_ = P2osFailureKind::kLink;
  }
  std::lock_guard lock(mutex_);
  finished_ = true;
  if (failure_.empty() && !stopping_) {
    failure_ = "connection ended";
    failure_kind_ = P2osFailureKind::kLink;
  }
  cv_.notify_all();
}

std::optional<mapper::SensorFrame> P2osRobot::next_frame() {
  std::unique_lock lock(mutex_);
  const std::uint64_t dropped_before = stats_.dropped_bytes;
  const std::uint64_t bad_sips_before = stats_.bad_sips;
  cv_.wait_for(lock, options_.frame_wait, [&] { return !frames_.empty() || finished_; });
  if (frames_.empty()) {
    if (!finished_ && !stopping_ && wait_expired_.empty()) {
      // The session ends here for the caller. A peer that completes every handshake but sends
      // no SIP (or none of a type this driver reads) reconnected every silence_timeout with
      // failure() empty, and `drive` wrote an empty run and exited 0.
      wait_expired_ = "no SIP in " + std::to_string(options_.frame_wait.count()) + " ms (" +
                      std::to_string(stats_.connections) + " handshakes, " +
                      std::to_string(stats_.sips) + " SIPs, " + std::to_string(stats_.bad_sips) +
                      " undecodable)";
      // Bytes that did not decode came instead of SIPs (SIPs with bad checksums, noise after
      // every handshake): bad input, not a silent robot.
      const std::uint64_t dropped = stats_.dropped_bytes - dropped_before;
      const std::uint64_t bad_sips = stats_.bad_sips - bad_sips_before;
      wait_expired_kind_ =
          dropped + bad_sips > 0 ? P2osFailureKind::kBadBytes : P2osFailureKind::kLink;
      if (dropped > 0) {
        wait_expired_ +=
            "; meanwhile " + std::to_string(dropped) +
            " bytes did not decode (the last discard: " + p2os_text::describe(last_drop_) + ")";
      }
      if (bad_sips > 0) wait_expired_ += "; the last undecodable " + last_bad_sip_reason_;
    }
    return std::nullopt;
  }
  mapper::SensorFrame f = std::move(frames_.front());
  frames_.pop_front();
  return f;
}

void P2osRobot::command(const mapper::VelocityCommand& cmd) {
  std::lock_guard lock(mutex_);
  motion_.v_mps = std::clamp(cmd.v_mps, -geometry_.max_speed_mps, geometry_.max_speed_mps);
  motion_.w_radps =
      std::clamp(cmd.w_radps, -geometry_.max_turn_rate_radps, geometry_.max_turn_rate_radps);
  motion_dirty_ = true;
}

void P2osRobot::stop() { command({}); }

void P2osRobot::shutdown() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    cv_.notify_all();
  }
  if (thread_.joinable()) thread_.join();
  std::lock_guard lock(mutex_);
  finished_ = true;
  frames_.clear();  // as documented: no frames after shutdown, not even queued ones
}

p2os::RobotIdentity P2osRobot::identity() const {
  std::lock_guard lock(mutex_);
  return identity_;
}

P2osStats P2osRobot::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

std::string P2osRobot::failure() const {
  std::lock_guard lock(mutex_);
  return failure_.empty() ? wait_expired_ : failure_;
}

P2osFailureKind P2osRobot::failure_kind() const {
  std::lock_guard lock(mutex_);
  return failure_.empty() ? wait_expired_kind_ : failure_kind_;
}

}  // namespace cogmap::hw
