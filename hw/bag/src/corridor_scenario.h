#pragma once
// Test support: a P3-DX driving 5 m down a 2 m corridor (walls at y = +1 m and y = -1 m of the
// odometry frame) at 0.1 m/s, recorded the way RosAria and p2os record it. Odometry at 10 Hz
// from stamp 1000.0 s; sonar messages 50 ms after each odometry sample (so every reading needs
// interpolation); the front ring fires two transducers per message (0 and 1, then 2 and 3, ...,
// as P2OS fires one disc per 40 ms), the rear ring is missing (never reports), and each firing's
// range carries a 0/1/2 mm offset (k mod 3) the way real ranges differ from firing to firing.
//
// Counts a correct import must report, derived by hand for N = 500 sonar messages x 16
// transducers:
// - rear 8 x N = 4000 values never reported; front transducers 2k, 2k+1 first fire at message k
//   (k = 0..3), so 2 x (0 + 1 + 2 + 3) = 12 more: 4012 never reported;
// - 2N = 1000 firings; the ±10° transducers (3 and 4) never hear a wall within 5 m, so each of
//   their N/4 = 125 firings after the first repeats the same no-echo value: 2 x 124 = 248 are
//   unchanged; accepted 1000 - 248 = 752, of which 2 without echo;
// - unchanged: 16 N - 4012 - 752 = 3236.

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "cogmap/hw/bag_import.h"
#include "cogmap/mapper/seam/robot_models.h"
#include "test_bag_writer.h"

namespace cogmap::hw::bag::testing {

/// Import options naming only the robot model.
inline BagImportOptions with_robot(const std::string& model) {
  BagImportOptions o;
  o.robot = model;
  return o;
}

struct CorridorCounts {
  static constexpr std::size_t kSonarMessages = 500;
  static constexpr std::size_t kOdometryMessages = 501;
  static constexpr std::size_t kAccepted = 752;
  static constexpr std::size_t kNoEcho = 2;
  static constexpr std::size_t kUnchanged = 3236;
  static constexpr std::size_t kUnreported = 4012;
};

inline constexpr double kT0 = 1000.0;     // first odometry stamp, s
inline constexpr double kSpeed = 0.1;     // m/s
inline constexpr double kWallY = 1.0;     // |y| of the walls, m
inline constexpr double kMaxRange = 5.0;  // ARIA's no-echo range, m

/// Odometry x at a time after kT0.
inline double corridor_x(double t_s) { return kSpeed * (t_s - kT0); }

/// The stamp of sonar message k.
inline double sonar_stamp(int k) { return kT0 + 0.1 * k + 0.05; }

/// Range transducer i measures in the corridor (from its mount to the wall along its heading),
/// or nullopt when no wall lies within kMaxRange. Firing offset (k mod 3) mm included.
inline std::optional<double> corridor_range(const mapper::SonarMount& m, int k) {
  const double s = std::sin(m.heading_rad);
  if (std::abs(s) < 1e-9) return std::nullopt;
  const double d = ((s > 0 ? kWallY : -kWallY) - m.y_m) / s;
  if (d > kMaxRange) return std::nullopt;
  return d + 0.001 * (k % 3);
}

/// Which front transducers fire in message k.
inline bool fires(int i, int k) { return i < 8 && (i == (2 * k) % 8 || i == (2 * k + 1) % 8); }

enum class SonarForm { kPointCloud, kPointCloud2, kSonarArray, kBothClouds };
enum class OdomForm { kOdometry, kTf };

/// Writes the corridor bag. RosAria topic names for clouds, p2os names for the SonarArray.
inline void write_corridor_bag(const std::string& path, SonarForm sonar, OdomForm odom,
                               Compression compression = Compression::kNone) {
  const mapper::RobotGeometry& g = mapper::find_robot_model("p3dx")->geometry;
  TestBagWriter bag(path, compression);
  std::vector<Xy> points(16);           // RosAria: last point of each transducer, origin first
  std::vector<double> ranges(16, 0.0);  // p2os: last range, 0 before the first
  const bool p2os = sonar == SonarForm::kSonarArray;
  const std::string odom_topic = p2os ? "/pose" : "/RosAria/pose";
  constexpr int n = static_cast<int>(CorridorCounts::kSonarMessages);
  for (int k = 0; k <= n; ++k) {
    const double t = kT0 + 0.1 * k;
    if (odom == OdomForm::kOdometry) {
      bag.odometry(odom_topic, t, corridor_x(t), 0.0, 0.0);
    } else {
      bag.tf("/tf", t, corridor_x(t), 0.0, 0.0);
    }
    if (k == n) break;
    for (int i = 0; i < 16; ++i) {
      if (!fires(i, k)) continue;
      const mapper::SonarMount& m = g.sonars[static_cast<std::size_t>(i)];
      const double r = corridor_range(m, k).value_or(kMaxRange);
      ranges[static_cast<std::size_t>(i)] = r;
      points[static_cast<std::size_t>(i)] = {m.x_m + r * std::cos(m.heading_rad),
                                             m.y_m + r * std::sin(m.heading_rad)};
    }
    const double ts = sonar_stamp(k);
    switch (sonar) {
      case SonarForm::kPointCloud:
        bag.point_cloud("/RosAria/sonar", ts, points);
        break;
      case SonarForm::kPointCloud2:
        bag.point_cloud2("/RosAria/sonar_pointcloud2", ts, points);
        break;
      case SonarForm::kBothClouds:
        bag.point_cloud("/RosAria/sonar", ts, points);
        bag.point_cloud2("/RosAria/sonar_pointcloud2", ts, points);
        break;
      case SonarForm::kSonarArray:
        bag.sonar_array("/sonar", ts, ranges);
        break;
    }
  }
}

}  // namespace cogmap::hw::bag::testing
