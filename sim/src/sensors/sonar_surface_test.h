#pragma once
/// The one ray-against-surface test every scan of the sonar model runs (internal): the full scan,
/// the cell walk of the scene index and the fan's nearest-first list all call these, so they run
/// the very same floating-point operations and give bit-identical answers.

#include <cmath>
#include <cstddef>
#include <optional>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/sim/sonar_model.h"

namespace cogmap::sim::sonar_detail {

// Rays start this far beyond their origin so a bounce never re-hits the surface it leaves.
inline constexpr double kMinT = 1e-9;

using mapper::cross;

/// Tests surface `i` against the ray origin + t·dir and keeps it if nearer than `best_t`.
/// Equally distant surfaces: the higher index wins, whatever order they are tested in. Only the
/// distance and the surface are kept; the hit point and normal are computed once at the end
/// (finish_hit), from the same operands, so they are the very same doubles. Returns true when
/// the surface was kept.
inline bool test_surface(const SonarScene& scene, int i, const mapper::Point2& origin,
                         const mapper::Point2& dir, double& best_t, int& best_i) {
  const mapper::Segment& s = scene.surfaces[static_cast<std::size_t>(i)];
  const mapper::Point2 e = s.b - s.a;
  const double denom = cross(dir, e);
  if (std::abs(denom) < 1e-15) return false;  // parallel: a grazing ray never echoes anyway
  const mapper::Point2 ao = s.a - origin;
  const double t = cross(ao, e) / denom;
  if (t <= kMinT || t > best_t) return false;  // u is not needed (the test below is an OR)
  const double u = cross(ao, dir) / denom;
  if (u < 0.0 || u > 1.0) return false;
  if (best_i >= 0 && t == best_t && i < best_i) return false;
  best_t = t;
  best_i = i;
  return true;
}

}  // namespace cogmap::sim::sonar_detail
