#include "cogmap/mapper/seam/fake_robot.h"

#include <utility>

namespace cogmap::mapper {

FakeRobot::FakeRobot(RobotGeometry geometry, std::vector<SensorFrame> frames)
    : geometry_(std::move(geometry)), frames_(std::move(frames)) {}

std::optional<SensorFrame> FakeRobot::next_frame() {
  if (next_ >= frames_.size()) return std::nullopt;
  return frames_[next_++];
}

void FakeRobot::command(const VelocityCommand& cmd) { commands_.push_back(cmd); }

void FakeRobot::stop() { commands_.push_back({}); }

}  // namespace cogmap::mapper
