#pragma once
/// A Robot that replays a scripted list of frames: for tests of everything above the seam.

#include <cstddef>
#include <vector>

#include "cogmap/mapper/seam/robot.h"

namespace cogmap::mapper {

class FakeRobot final : public Robot {
 public:
  FakeRobot(RobotGeometry geometry, std::vector<SensorFrame> frames);

  const RobotGeometry& geometry() const override { return geometry_; }
  std::optional<SensorFrame> next_frame() override;
  void command(const VelocityCommand& cmd) override;
  void stop() override;

  /// Every command received, in order (stop() records a zero command).
  const std::vector<VelocityCommand>& commands() const { return commands_; }

 private:
  RobotGeometry geometry_;
  std::vector<SensorFrame> frames_;
  std::size_t next_ = 0;
  std::vector<VelocityCommand> commands_;
};

}  // namespace cogmap::mapper
