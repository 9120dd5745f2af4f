#pragma once
/// Scene builders and reference formulas shared by the sonar tests: exact synthetic geometry
/// around one transducer, and the model's equations written out independently of the code.

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/sim/sonar_model.h"

namespace cogmap::sim::testing {

inline constexpr double kDeg = std::numbers::pi / 180.0;

/// Where transducer `index` sits and points when the robot is at `pose` (world frame).
struct TransducerFrame {
  mapper::Point2 origin;
  double axis_rad = 0.0;
  mapper::Point2 along(double distance_m, double offset_rad = 0.0) const {
    return origin + distance_m * mapper::Point2(std::cos(axis_rad + offset_rad),
                                                std::sin(axis_rad + offset_rad));
  }
};

inline TransducerFrame transducer_frame(const mapper::RobotGeometry& g, const mapper::Pose2& pose,
                                        int index) {
  const mapper::SonarMount& m = g.sonars[static_cast<std::size_t>(index)];
  return {pose.transform(mapper::Point2(m.x_m, m.y_m)), pose.theta_rad + m.heading_rad};
}

/// One transducer at the robot's origin looking along +x (0.1-5 m): with the identity pose the
/// beam axis is exactly the world x axis, so distances along it are exact.
inline mapper::RobotGeometry single_transducer_geometry() {
  mapper::RobotGeometry g;
  g.sonars = {mapper::SonarMount{0.0, 0.0, 0.0}};
  g.sonar_min_range_m = 0.1;
  g.sonar_max_range_m = 5.0;
  return g;
}

/// A segment through `center` along heading `heading_rad`, `half_length_m` each way.
inline mapper::Segment segment_through(const mapper::Point2& center, double heading_rad,
                                       double half_length_m) {
  const mapper::Point2 d(std::cos(heading_rad), std::sin(heading_rad));
  return {center - half_length_m * d, center + half_length_m * d};
}

/// A scene with every member given (SonarScene has four; brace-init needs all of them).
inline SonarScene scene_of(std::vector<mapper::Segment> surfaces,
                           std::vector<mapper::Point2> corners = {},
                           std::vector<int> surface_material = {},
                           std::vector<SonarMaterial> materials = {}) {
  return {std::move(surfaces), std::move(corners), std::move(surface_material),
          std::move(materials)};
}

/// Index of a built-in material by name, found by a plain scan of the table (-1: none).
inline int builtin_index(const std::string& name) {
  const std::vector<SonarMaterial>& t = builtin_sonar_materials();
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

/// The built-in material of that name.
inline const SonarMaterial& builtin(const char* name) {
  return builtin_sonar_materials()[static_cast<std::size_t>(builtin_index(name))];
}

/// The options every worked example assumes, written out so that a change of the defaults does
/// not move the expected values: sd 6 deg, 21 rays over +/-25 deg (2.5 deg apart, ray 10 on the
/// axis), 0 dB, corners 20, walk 0.15 m, range gain exponent 1, noise 1 % + 1 cm, 1 % dropouts.
inline SonarModelOptions reference_options() {
  SonarModelOptions o;
  o.beam_sigma_deg = 6.0;
  o.fan_half_width_deg = 25.0;
  o.rays_per_cone = 21;
  o.detection_gain_db = 0.0;
  o.corner_strength = 20.0;
  o.diffuse_range_gain_exponent = 1.0;
  o.threshold_walk_m = 0.15;
  o.range_noise_fraction = 0.01;
  o.range_noise_floor_m = 0.01;
  o.dropout_probability = 0.01;
  o.multipath = true;
  o.corner_radius_m = 0.05;
  return o;
}

/// reference_options() with neither noise nor dropouts nor threshold walk, so readings equal the
/// range of the first heard candidate.
inline SonarModelOptions noiseless_sonar_options() {
  SonarModelOptions o = reference_options();
  o.range_noise_fraction = 0.0;
  o.range_noise_floor_m = 0.0;
  o.dropout_probability = 0.0;
  o.threshold_walk_m = 0.0;
  return o;
}

/// The two-way beam pattern, a Gaussian of sd sigma in the offset from the axis.
inline double reference_beam(double offset_rad, double sigma_rad) {
  return std::exp(-(offset_rad * offset_rad) / (2.0 * sigma_rad * sigma_rad));
}

/// The normal probability density of x with sd s.
inline double normal_pdf(double x, double s) {
  return std::exp(-(x * x) / (2.0 * s * s)) / (s * std::sqrt(2.0 * std::numbers::pi));
}

/// Expected detections of one ray's share `dphi_rad` of a surface hit at `incidence_rad` after a
/// path of one-way length `range_m` (docs/sonar-model.md): a mirror lobe whose density over the
/// incidence integrates to specular_strength, plus diffuse backscatter D cos^n(i) (r / 1 m)^g.
inline double reference_surface_strength(const SonarMaterial& m, double incidence_rad,
                                         double range_m, double range_gain_exponent,
                                         double dphi_rad) {
  const double mirror = m.specular_strength * normal_pdf(incidence_rad, m.specular_lobe_deg * kDeg);
  const double diffuse = m.diffuse_strength *
                         std::pow(std::cos(incidence_rad), m.diffuse_incidence_exponent) *
                         std::pow(range_m, range_gain_exponent);
  return (mirror + diffuse) * dphi_rad;
}

/// Offset of ray i of n across +/- fan (the model's fan: evenly spaced, ends included).
inline double ray_offset_rad(int i, int n, double fan_half_width_deg) {
  return n == 1 ? 0.0 : (-1.0 + 2.0 * i / (n - 1.0)) * fan_half_width_deg * kDeg;
}

/// Angular width one ray of n stands for, radians.
inline double ray_width_rad(int n, double fan_half_width_deg) {
  return 2.0 * fan_half_width_deg * kDeg / (n == 1 ? 1.0 : n - 1.0);
}

}  // namespace cogmap::sim::testing
