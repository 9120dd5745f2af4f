// The start-enclosure warning (world_enclosure.h): rays from the start against every solid
// piece of the world.
#include "cogmap/sim/world_enclosure.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "cogmap/sim/world_geometry.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;

// Whether the ray from `p` along `d` crosses the segment a-b (ends included: a ray through a
// joint of two pieces meets them). Parallel segments are skipped: every closed outline has
// other edges across the ray.
bool ray_meets(const Point2& p, const Point2& d, const Point2& a, const Point2& b) {
  const Point2 e = b - a;
  const double denom = mapper::cross(d, e);
  if (std::abs(denom) < 1e-12 * e.norm()) return false;
  const Point2 ap = a - p;
  const double t = mapper::cross(ap, e) / denom;
  const double u = mapper::cross(ap, d) / denom;
  return t > 0.0 && u >= -1e-9 && u <= 1.0 + 1e-9;
}

}  // namespace

int open_directions(const WorldSpec& world, const mapper::Point2& from, int directions) {
  const std::vector<SolidPiece> pieces = solid_pieces(world);
  int open = 0;
  for (int k = 0; k < directions; ++k) {
    const double a = 2.0 * std::numbers::pi * k / directions;
    const Point2 d{std::cos(a), std::sin(a)};
    bool met = false;
    for (const SolidPiece& piece : pieces) {
      const mapper::Polyline& o = piece.outline;
      for (std::size_t i = 0; i < o.size() && !met; ++i) {
        met = ray_meets(from, d, o[i], o[(i + 1) % o.size()]);
      }
      if (met) break;
    }
    if (!met) ++open;
  }
  return open;
}

std::optional<std::string> start_enclosure_warning(const WorldSpec& world,
                                                   const mapper::Point2& start) {
  // The rays are unbounded, not cut at the sonar's 5 m: a start in a large room or in a long
  // corridor (the 78 m hallway loop, the 40 m calibration corridor) hears nothing at first and
  // is still inside. A quarter: inside a room only its doorways let rays out (a 1 m door 2 m
  // away lets out 2 or 3 of 32), while from outside a building, whose outline subtends less
  // than half a turn, at least 16 of 32 escape; one wall alone lets out more than half.
  const int open = open_directions(world, start);
  if (open * 4 <= kEnclosureDirections) return std::nullopt;
  std::ostringstream msg;
  msg.setf(std::ios::fixed);
  msg.precision(2);
  msg << "start (" << start.x() << ", " << start.y() << ") is not enclosed by walls: " << open
      << " of " << kEnclosureDirections
      << " directions from it meet no wall or obstacle at any distance (outside the building? "
         "the robot would hear nothing there)";
  return msg.str();
}

}  // namespace cogmap::sim
