#pragma once
/// Record and replay at the seam: RecordingRobot wraps any Robot and writes the cogmap log;
/// LogRobot replays a log as a Robot.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>

#include "cogmap/hw/robot_log.h"
#include "cogmap/mapper/seam/robot.h"

namespace cogmap::hw {

/// Passes everything through to `inner` and logs every frame and command (one flushed line
/// each). `inner` must outlive this object.
class RecordingRobot final : public mapper::Robot {
 public:
  /// Creates the log. Throws std::runtime_error naming the file when it cannot be written.
  RecordingRobot(mapper::Robot& inner, const std::filesystem::path& log_path);

  const mapper::RobotGeometry& geometry() const override { return inner_.geometry(); }
  std::optional<mapper::SensorFrame> next_frame() override;
  void command(const mapper::VelocityCommand& cmd) override;
  void stop() override;

 private:
  mapper::Robot& inner_;
  LogWriter writer_;
  double last_time_s_ = 0.0;
};

/// Replays a cogmap log: frames in order, commands ignored, empty at end of file. The whole
/// file is validated when constructed, so a malformed line fails before a run starts.
class LogRobot final : public mapper::Robot {
 public:
  /// Throws LogError ("file:line: expected ...") for a missing or malformed log.
  explicit LogRobot(const std::filesystem::path& path);

  const mapper::RobotGeometry& geometry() const override { return reader_.geometry(); }
  std::optional<mapper::SensorFrame> next_frame() override;
  void command(const mapper::VelocityCommand&) override {}
  void stop() override {}

  /// Frames in the log.
  std::size_t frame_count() const { return frame_count_; }
  /// True when every frame carries a true pose (a recorded simulation).
  bool has_true_poses() const { return frame_count_ > 0 && truth_count_ == frame_count_; }
  /// The first frame's true pose, when present.
  const std::optional<mapper::Pose2>& first_true_pose() const { return first_true_pose_; }
  /// The time of the last frame, seconds.
  double last_time_s() const { return last_time_s_; }

 private:
  // Declared before reader_: the validation pass that builds reader_ fills them in.
  std::size_t frame_count_ = 0;
  std::size_t truth_count_ = 0;
  std::optional<mapper::Pose2> first_true_pose_;
  double last_time_s_ = 0.0;
  LogReader reader_;
};

}  // namespace cogmap::hw
