#pragma once
// Test-only ByteStream decorators and a kinematic robot body for the robot-side server.

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <random>
#include <vector>

#include "cogmap/hw/byte_stream.h"
#include "cogmap/hw/p2os_packet.h"
#include "cogmap/hw/p2os_robot.h"
#include "cogmap/mapper/seam/robot.h"

namespace cogmap::hw::testing {

/// Flips one byte in every `period` written (position within the period drawn from a fixed
/// seed), emulating a USB-serial adapter that corrupts now and then.
class CorruptingStream final : public ByteStream {
 public:
  CorruptingStream(ByteStream& inner, std::size_t period, std::uint32_t seed)
      : inner_(inner), period_(period), rng_(seed) {
    next_ = rng_() % period_;
  }
  void write(std::span<const std::uint8_t> bytes) override {
    std::vector<std::uint8_t> copy(bytes.begin(), bytes.end());
    for (auto& b : copy) {
      if (written_++ == next_) {
        b ^= static_cast<std::uint8_t>(1 + rng_() % 255);
        ++flipped_;
        next_ = (written_ / period_ + 1) * period_ + rng_() % period_;
      }
    }
    inner_.write(copy);
  }
  std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
    return inner_.read(buffer, timeout);
  }
  std::string name() const override { return "corrupting:" + inner_.name(); }
  std::size_t flipped() const { return flipped_; }

 private:
  ByteStream& inner_;
  std::size_t period_;
  std::mt19937 rng_;
  std::size_t written_ = 0;
  std::size_t next_ = 0;
  std::size_t flipped_ = 0;
};

/// Drops every write while `silent` is set: a cable pulled out and put back.
class SilenceableStream final : public ByteStream {
 public:
  explicit SilenceableStream(ByteStream& inner) : inner_(inner) {}
  void write(std::span<const std::uint8_t> bytes) override {
    if (!silent) inner_.write(bytes);
  }
  std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
    return inner_.read(buffer, timeout);
  }
  std::string name() const override { return inner_.name(); }
  std::atomic<bool> silent{false};

 private:
  ByteStream& inner_;
};

/// Reports the link as no longer taking bytes while `backed_up` is set: a pty or socket whose
/// reader is gone and whose buffer has filled (writes still go through, to keep tests simple).
class BackedUpStream final : public ByteStream {
 public:
  explicit BackedUpStream(ByteStream& inner) : inner_(inner) {}
  void write(std::span<const std::uint8_t> bytes) override { inner_.write(bytes); }
  std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
    return inner_.read(buffer, timeout);
  }
  std::string name() const override { return inner_.name(); }
  bool accepts_writes() override { return !backed_up; }
  std::atomic<bool> backed_up{false};

 private:
  ByteStream& inner_;
};

/// Records the arrival time and type of every client packet the server reads.
class TappingStream final : public ByteStream {
 public:
  explicit TappingStream(ByteStream& inner) : inner_(inner) {}
  void write(std::span<const std::uint8_t> bytes) override { inner_.write(bytes); }
  std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
    const std::size_t n = inner_.read(buffer, timeout);
    if (n > 0) {
      std::lock_guard lock(mutex_);
      decoder_.feed(buffer.first(n));
      while (auto p = decoder_.next()) {
        arrivals_.push_back({std::chrono::steady_clock::now(), p->type()});
      }
    }
    return n;
  }
  std::string name() const override { return inner_.name(); }
  struct Arrival {
    std::chrono::steady_clock::time_point time;
    std::uint8_t type;
  };
  std::vector<Arrival> arrivals() const {
    std::lock_guard lock(mutex_);
    return arrivals_;
  }

 private:
  ByteStream& inner_;
  mutable std::mutex mutex_;
  p2os::PacketDecoder decoder_;
  std::vector<Arrival> arrivals_;
};

/// A unicycle that integrates its command every 100 ms and reports four sonars a frame
/// (ranges 1.0 + 0.1 index m; transducer 15 never echoes). Thread-safe enough for one server.
class KinematicBody final : public mapper::Robot {
 public:
  KinematicBody() : geometry_(mapper::p2at_geometry()) {}
  const mapper::RobotGeometry& geometry() const override { return geometry_; }
  std::optional<mapper::SensorFrame> next_frame() override {
    std::lock_guard lock(mutex_);
    pose_.theta_rad += cmd_.w_radps * 0.1;
    pose_.x_m += std::cos(pose_.theta_rad) * cmd_.v_mps * 0.1;
    pose_.y_m += std::sin(pose_.theta_rad) * cmd_.v_mps * 0.1;
    distance_m_ += std::abs(cmd_.v_mps) * 0.1;
    mapper::SensorFrame f;
    f.time_s = 0.1 * static_cast<double>(++cycles_);
    f.odometry = {pose_.x_m, pose_.y_m, mapper::wrap_angle_rad(pose_.theta_rad)};
    for (int k = 0; k < 4; ++k) {
      const int i = static_cast<int>((cycles_ * 4 + k) % 16);
      mapper::SonarReading r;
      r.index = i;
      r.echo = i != 15;
      r.range_m = r.echo ? 1.0 + 0.1 * i : geometry_.sonar_max_range_m;
      f.sonar.push_back(r);
    }
    return f;
  }
  void command(const mapper::VelocityCommand& cmd) override {
    std::lock_guard lock(mutex_);
    cmd_ = cmd;
  }
  void stop() override { command({}); }
  /// Moves the body dx_m along x at once: odometry no robot could drive.
  void teleport(double dx_m) {
    std::lock_guard lock(mutex_);
    pose_.x_m += dx_m;
  }
  double distance_m() const {
    std::lock_guard lock(mutex_);
    return distance_m_;
  }
  mapper::VelocityCommand current() const {
    std::lock_guard lock(mutex_);
    return cmd_;
  }

 private:
  mapper::RobotGeometry geometry_;
  mutable std::mutex mutex_;
  mapper::Pose2 pose_;
  mapper::VelocityCommand cmd_;
  std::uint64_t cycles_ = 0;
  double distance_m_ = 0.0;
};

/// The frames `robot` delivers within `span` of wall time (fewer if its session ends).
inline std::vector<mapper::SensorFrame> frames_for(P2osRobot& robot,
                                                   std::chrono::milliseconds span) {
  std::vector<mapper::SensorFrame> frames;
  const auto end = std::chrono::steady_clock::now() + span;
  while (std::chrono::steady_clock::now() < end) {
    auto f = robot.next_frame();
    if (!f) break;
    frames.push_back(std::move(*f));
  }
  return frames;
}

}  // namespace cogmap::hw::testing
