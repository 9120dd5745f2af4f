#include "cogmap/sim/stall_detector.h"

#include <cmath>

namespace cogmap::sim {

void StallDetector::update(const WheelSpeeds& wheels, const BodyTwist& expected,
                           const BodyTwist& actual, bool in_contact, double dt_s) {
  const double half = 0.5 * options_.track_m;
  update_side(left_, wheels.left_mps, expected.v_mps - expected.w_radps * half,
              actual.v_mps - actual.w_radps * half, in_contact, dt_s);
  update_side(right_, wheels.right_mps, expected.v_mps + expected.w_radps * half,
              actual.v_mps + actual.w_radps * half, in_contact, dt_s);
}

void StallDetector::update_side(Side& side, double wheel_mps, double expected_mps,
                                double actual_mps, bool in_contact, double dt_s) const {
  const bool driven = std::abs(wheel_mps) >= options_.min_wheel_mps && std::abs(expected_mps) > 0.0;
  // Progress along the direction the side should move; moving backwards counts as none.
  const double progress = std::copysign(1.0, expected_mps) * actual_mps;
  const bool slow = driven && progress < options_.speed_fraction * std::abs(expected_mps);
  side.slow_s = slow ? side.slow_s + dt_s : 0.0;
  side.stalled = slow && (side.slow_s > options_.persist_s || in_contact);
}

}  // namespace cogmap::sim
