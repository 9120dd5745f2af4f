#pragma once

namespace cogmap::mapper {

/// A motion command in the robot frame.
struct VelocityCommand {
  double v_mps = 0.0;    ///< forward speed, metres per second
  double w_radps = 0.0;  ///< turn rate, radians per second, counter-clockwise positive
};

}  // namespace cogmap::mapper
