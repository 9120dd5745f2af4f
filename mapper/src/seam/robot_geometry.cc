#include "cogmap/mapper/seam/robot_geometry.h"

#include <array>
#include <numbers>

namespace cogmap::mapper {

RobotGeometry p2at_geometry() {
  // x_mm, y_mm, heading_deg per transducer: the ARIA p2at.p parameter file (docs/p2at.md).
  struct Mount {
    double x_mm, y_mm, heading_deg;
  };
  static constexpr std::array<Mount, 16> kMounts{{{147, 136, 90},
                                                  {193, 119, 50},
                                                  {227, 79, 30},
                                                  {245, 27, 10},
                                                  {245, -27, -10},
                                                  {227, -79, -30},
                                                  {193, -119, -50},
                                                  {147, -136, -90},
                                                  {-144, -136, -90},
                                                  {-189, -119, -130},
                                                  {-223, -79, -150},
                                                  {-241, -27, -170},
                                                  {-241, 27, 170},
                                                  {-223, 79, 150},
                                                  {-189, 119, 130},
                                                  {-144, 136, 90}}};
  RobotGeometry g;
  for (const Mount& m : kMounts) {
    g.sonars.push_back(
        {m.x_mm / 1000.0, m.y_mm / 1000.0, m.heading_deg * std::numbers::pi / 180.0});
  }
  g.sonar_min_range_m = 0.1;
  g.sonar_max_range_m = 5.0;
  g.sonar_beam_width_rad = 30.0 * std::numbers::pi / 180.0;
  g.length_m = 0.626;
  g.width_m = 0.505;
  g.max_speed_mps = 0.75;
  g.max_turn_rate_radps = 1.74;
  g.max_accel_mps2 = 0.3;
  g.max_decel_mps2 = 0.6;
  return g;
}

}  // namespace cogmap::mapper
