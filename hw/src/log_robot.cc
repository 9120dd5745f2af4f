// RecordingRobot and LogRobot.
#include "cogmap/hw/log_robot.h"

namespace cogmap::hw {

RecordingRobot::RecordingRobot(mapper::Robot& inner, const std::filesystem::path& log_path)
    : inner_(inner), writer_(log_path, inner.geometry()) {}

std::optional<mapper::SensorFrame> RecordingRobot::next_frame() {
  std::optional<mapper::SensorFrame> f = inner_.next_frame();
  if (f) {
    writer_.write_line(format_frame_line(*f));
    last_time_s_ = f->time_s;
  }
  return f;
}

void RecordingRobot::command(const mapper::VelocityCommand& cmd) {
  writer_.write_line(format_command_line(last_time_s_, cmd));
  inner_.command(cmd);
}

void RecordingRobot::stop() {
  writer_.write_line(format_stop_line(last_time_s_));
  inner_.stop();
}

namespace {
// Reads the whole log once: every malformed line surfaces here, before any run starts.
LogReader validated(const std::filesystem::path& path, std::size_t& frames, std::size_t& truths,
                    std::optional<mapper::Pose2>& first_truth, double& last_time_s) {
  LogReader check(path);
  while (auto item = check.next()) {
    if (const auto* f = std::get_if<mapper::SensorFrame>(&*item)) {
      ++frames;
      if (f->true_pose) {
        ++truths;
        if (!first_truth && frames == 1) first_truth = f->true_pose;
      }
      last_time_s = f->time_s;
    }
  }
  // A header alone would "map" nothing and exit 0 with 0 rooms: that is a wrong file.
  if (frames == 0) {
    throw LogError(path.string() + ":" + std::to_string(check.line()) +
                   ": the log has a header but no frames (F lines): nothing to replay");
  }
  return LogReader(path);
}
}  // namespace

LogRobot::LogRobot(const std::filesystem::path& path)
    : reader_(validated(path, frame_count_, truth_count_, first_true_pose_, last_time_s_)) {}

std::optional<mapper::SensorFrame> LogRobot::next_frame() {
  while (auto item = reader_.next()) {
    if (auto* f = std::get_if<mapper::SensorFrame>(&*item)) return std::move(*f);
  }
  return std::nullopt;
}

}  // namespace cogmap::hw
