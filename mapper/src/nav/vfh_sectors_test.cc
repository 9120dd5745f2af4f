// Vfh::build finds each obstacle's enlarged sectors from its direction turned by ±γ, without
// atan2 or asin: its histogram must be the one the angles gave (kept here as the reference), bit
// for bit, also for obstacles at sector borders, inside the safety radius and at its edge.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "cogmap/mapper/nav/vfh.h"
#include "nav/nav_test_util.h"

namespace cogmap::mapper::nav {
namespace {

/// Eq. 2.17 by the angles, as Vfh::build did before 2026-12-03.
std::vector<double> reference_density(const Vfh& vfh, const VfhOptions& options,
                                      const std::vector<ObstaclePoint>& obstacles) {
  const int n = vfh.sector_count();
  std::vector<double> density(static_cast<std::size_t>(n), 0.0);
  for (const ObstaclePoint& o : obstacles) {
    const double d = o.offset_m.norm();
    const double kappa = vfh.kappa_at(d);
    if (kappa <= 0.0 || d <= 0.0) continue;
    const double beta = std::atan2(o.offset_m.y(), o.offset_m.x());
    const double m = static_cast<double>(o.certainty) * o.certainty * kappa;
    const double r = options.safety_radius_m;
    const double gamma = d > r ? std::asin(r / d) : 0.5 * std::numbers::pi;
    const int lo = vfh.sector_of(beta - gamma);
    const int span = ((vfh.sector_of(beta + gamma) - lo) % n + n) % n;
    for (int i = 0, k = lo; i <= span; ++i) {
      density[static_cast<std::size_t>(k)] += m;
      if (++k == n) k = 0;
    }
  }
  return density;
}

using testing::at;

TEST(VfhSectors, DensityMatchesTheAnglesBitForBit) {
  std::mt19937_64 rng(1203);
  std::uniform_real_distribution<double> u(-2.6, 2.6), unit(0.0, 1.0), angle(-3.2, 3.2);
  for (const double sector_deg : {5.0, 10.0, 7.0}) {
    VfhOptions options;
    options.sector_deg = sector_deg;
    Vfh vfh(options);
    const double s = 2.0 * std::numbers::pi / vfh.sector_count();
    const double r = options.safety_radius_m;
    for (int k = 0; k < 3000; ++k) {
      std::vector<ObstaclePoint> points;
      const int count = 1 + static_cast<int>(unit(rng) * 60);
      for (int i = 0; i < count; ++i) {
        const float c = static_cast<float>(1.0 + 14.0 * unit(rng));
        const double range = 0.05 + 2.5 * unit(rng);
        switch (i % 6) {
          case 0:
            points.push_back({Point2(u(rng), u(rng)), c});
            break;
          case 1: {  // an enlarged edge exactly on a sector border
            const double border = (std::floor(unit(rng) * 72) - 0.5) * s;
            const double gamma = range > r ? std::asin(r / range) : 0.5 * std::numbers::pi;
            points.push_back({at(border + (i % 2 ? gamma : -gamma), range), c});
            break;
          }
          case 2:  // the bearing itself on a border
            points.push_back({at((std::floor(unit(rng) * 72) - 0.5) * s, range), c});
            break;
          case 3:  // inside the safety radius, at its edge, just outside
            points.push_back({at(angle(rng), r * (0.5 + 0.5 * (i % 3)) + 1e-4 * unit(rng)), c});
            break;
          case 4:  // along the axes, where the rough bearing's octants meet
            points.push_back({at(0.25 * std::numbers::pi * std::floor(unit(rng) * 8), range), c});
            break;
          default:  // cell centres of a 0.1 m grid
            points.push_back({Point2(0.1 * std::round(u(rng) * 10.0) + 0.05,
                                     0.1 * std::round(u(rng) * 10.0) - 0.05),
                              c});
        }
      }
      vfh.build(points);
      const std::vector<double> expected = reference_density(vfh, options, points);
      ASSERT_EQ(vfh.density().size(), expected.size());
      for (std::size_t j = 0; j < expected.size(); ++j) {
        ASSERT_EQ(std::memcmp(&vfh.density()[j], &expected[j], sizeof(double)), 0)
            << "sector " << j << " case " << k << " (" << sector_deg << "° sectors)";
      }
    }
  }
}

}  // namespace
}  // namespace cogmap::mapper::nav
